// Chi-square goodness of fit of every BSDF's sampling routine against its pdf (the pbrt / Mitsuba
// test): sampled directions are binned in (theta, phi) over the whole sphere and compared with the
// pdf integrated over each cell; delta lobes and failed samples fall into one extra cell that
// expects 1 - (integral of the pdf). Also: the pdf integrates to at most 1, and every sample's
// weight * pdf equals bsdfEval.
#include "chi_square.h"
#include "renderer/cpu_twin/glsl_twin.h"

#include <QtTest>

#include <cmath>
#include <vector>

using namespace glint::twin;
using glint::twin::test::chiSquareTest;

namespace {

constexpr int kThetaCells = 10;
constexpr int kPhiCells = 20;
constexpr int kSamples = 200000;
constexpr int kConfigurations = 26; // rows of sampleMatchesPdf_data, for the Sidak correction

vec3 directionAt(double theta, double phi) {
    return vec3(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)), float(std::cos(theta)));
}

int cellOf(vec3 w) {
    double theta = std::acos(std::clamp(double(w.z), -1.0, 1.0));
    double phi = std::atan2(double(w.y), double(w.x));
    if (phi < 0.0) phi += 2.0 * M_PI;
    int t = std::min(int(theta / M_PI * kThetaCells), kThetaCells - 1);
    int p = std::min(int(phi / (2.0 * M_PI) * kPhiCells), kPhiCells - 1);
    return t * kPhiCells + p;
}

// Integral of density * sin(theta) over a rectangle in (theta, phi), refined where the midpoint
// rule on 2x2 children disagrees with the parent's (peaked GGX lobes at low roughness).
template <typename Density> // double(double theta, double phi)
double integrateAdaptive(const Density& pdf, double t0, double t1, double p0, double p1, double coarse, int depth,
                         int minDepth) {
    double tm = 0.5 * (t0 + t1);
    double pm = 0.5 * (p0 + p1);
    auto midpoint = [&](double a0, double a1, double b0, double b1) {
        double t = 0.5 * (a0 + a1);
        return pdf(t, 0.5 * (b0 + b1)) * std::sin(t) * (a1 - a0) * (b1 - b0);
    };
    double c[4] = {midpoint(t0, tm, p0, pm), midpoint(tm, t1, p0, pm), midpoint(t0, tm, pm, p1), midpoint(tm, t1, pm, p1)};
    double fine = c[0] + c[1] + c[2] + c[3];
    if (depth == 0 || (minDepth <= 0 && std::abs(fine - coarse) < 1e-7 + 1e-3 * fine)) return fine;
    return integrateAdaptive(pdf, t0, tm, p0, pm, c[0], depth - 1, minDepth - 1) +
           integrateAdaptive(pdf, tm, t1, p0, pm, c[1], depth - 1, minDepth - 1) +
           integrateAdaptive(pdf, t0, tm, pm, p1, c[2], depth - 1, minDepth - 1) +
           integrateAdaptive(pdf, tm, t1, pm, p1, c[3], depth - 1, minDepth - 1);
}

template <typename Density>
std::vector<double> integratedCells(const Density& pdf) {
    constexpr int sub = 8;
    std::vector<double> cells(kThetaCells * kPhiCells, 0.0);
    double dt = M_PI / kThetaCells / sub;
    double dp = 2.0 * M_PI / kPhiCells / sub;
    for (int t = 0; t < kThetaCells * sub; ++t) {
        for (int p = 0; p < kPhiCells * sub; ++p) {
            double t0 = t * dt, p0 = p * dp;
            double coarse = pdf(t0 + 0.5 * dt, p0 + 0.5 * dp) * std::sin(t0 + 0.5 * dt) * dt * dp;
            cells[(t / sub) * kPhiCells + p / sub] += integrateAdaptive(pdf, t0, t0 + dt, p0, p0 + dp, coarse, 6, 2);
        }
    }
    return cells;
}

SurfaceMaterial material(vec3 baseColor, float metallic, float roughness, float transmission, bool thinWalled) {
    SurfaceMaterial m = defaultSurfaceMaterial();
    m.baseColor = baseColor;
    m.metallic = metallic;
    m.roughness = roughness;
    m.transmission = transmission;
    m.thinWalled = thinWalled;
    return m;
}

vec3 incident(float cosTheta) { return normalize(vec3(std::sqrt(1.0f - cosTheta * cosTheta), 0.3f * (1.0f - std::abs(cosTheta)), cosTheta)); }

} // namespace

Q_DECLARE_METATYPE(SurfaceMaterial)

class TwinBsdfSamplingTest : public QObject {
    Q_OBJECT
private slots:
    void sampleMatchesPdf_data() {
        QTest::addColumn<SurfaceMaterial>("m");
        QTest::addColumn<float>("cosWo");
        SurfaceMaterial lambert = material(vec3(0.8f), 0.0f, 1.0f, 0.0f, true);
        lambert.specularFactor = 0.0f;
        QTest::newRow("lambert normal") << lambert << 1.0f;
        QTest::newRow("lambert grazing") << lambert << 0.1f;
        for (float roughness : {0.1f, 0.3f, 0.6f, 1.0f}) {
            for (float cosWo : {0.9f, 0.5f, 0.15f}) {
                QTest::newRow(qPrintable(QString("metal r%1 cos%2").arg(roughness).arg(cosWo)))
                    << material(vec3(0.9f, 0.6f, 0.3f), 1.0f, roughness, 0.0f, true) << cosWo;
            }
        }
        QTest::newRow("plastic r0.3") << material(vec3(0.5f), 0.0f, 0.3f, 0.0f, true) << 0.6f;
        QTest::newRow("plastic r0.6 grazing") << material(vec3(0.5f), 0.0f, 0.6f, 0.0f, true) << 0.2f;
        QTest::newRow("half metal r0.5") << material(vec3(0.7f), 0.5f, 0.5f, 0.0f, true) << 0.7f;
        QTest::newRow("rough glass r0.3 outside") << material(vec3(1.0f), 0.0f, 0.3f, 1.0f, false) << 0.7f;
        QTest::newRow("rough glass r0.6 outside") << material(vec3(1.0f), 0.0f, 0.6f, 1.0f, false) << 0.3f;
        QTest::newRow("rough glass r0.3 inside") << material(vec3(1.0f), 0.0f, 0.3f, 1.0f, false) << -0.8f;
        QTest::newRow("rough glass r0.5 inside TIR") << material(vec3(1.0f), 0.0f, 0.5f, 1.0f, false) << -0.4f;
        QTest::newRow("rough thin glass r0.4") << material(vec3(0.9f), 0.0f, 0.4f, 1.0f, true) << 0.6f;
        QTest::newRow("smooth glass + rough plastic") << material(vec3(0.8f), 0.0f, 0.02f, 0.5f, false) << 0.6f;
        QTest::newRow("glass half transmission r0.5") << material(vec3(0.8f), 0.0f, 0.5f, 0.5f, false) << 0.5f;
    }

    void sampleMatchesPdf() {
        QFETCH(SurfaceMaterial, m);
        QFETCH(float, cosWo);
        vec3 wo = incident(cosWo);
        std::vector<double> observed(kThetaCells * kPhiCells + 1, 0.0);
        Rng rng = rngStart(uvec2(qHash(QByteArray(QTest::currentDataTag())), 1u), 0u, 5u);
        int mismatches = 0;
        for (int i = 0; i < kSamples; ++i) {
            BsdfSample s;
            if (!bsdfSample(m, wo, rand3(rng), s) || (s.lobe & LOBE_SPECULAR) != 0u) {
                observed.back() += 1.0;
                continue;
            }
            ++observed[cellOf(s.wi)];
            float pdf;
            vec3 f = bsdfEval(m, wo, s.wi, pdf);
            bool consistent = std::abs(pdf - s.pdf) <= 1e-4f * pdf && length(f - s.weight * s.pdf) <= 1e-4f * length(f) + 1e-7f;
            mismatches += consistent && isFiniteVec3(s.weight) ? 0 : 1;
        }
        std::vector<double> expected = integratedCells([&](double theta, double phi) {
            return double(bsdfPdf(m, wo, directionAt(theta, phi)));
        });
        double total = 0.0;
        for (double& e : expected) {
            total += e;
            e *= kSamples;
        }
        expected.push_back(std::max(0.0, 1.0 - total) * kSamples);
        QCOMPARE(mismatches, 0);
        QVERIFY2(total <= 1.0 + 1e-3, qPrintable(QString("pdf integrates to %1").arg(total)));
        auto result = chiSquareTest(observed, expected);
        qInfo("%s: %s", QTest::currentDataTag(), result.message.c_str());
        QVERIFY2(result.pValue > glint::twin::test::sidakSignificance(0.01, kConfigurations), result.message.c_str());
    }
};

QTEST_APPLESS_MAIN(TwinBsdfSamplingTest)
#include "test_twin_bsdf_sampling.moc"
