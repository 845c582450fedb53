// The media sampling code the path tracer runs (shaders/sampling/phase.glsl, fog_density.glsl),
// compiled as C++: Henyey-Greenstein sampling passes Pearson's chi-square test against the phase
// function integrated over cells, the phase function integrates to 1 and the sampler's pdf is its
// value; the height fog's closed-form optical depth matches numerical integration of the density,
// and the closed-form inverse gives back the distance.
#include "chi_square.h"
#include "renderer/cpu_twin/glsl_twin.h"

#include <QtTest>

#include <cmath>
#include <random>
#include <vector>

using namespace glint::twin;
using glint::twin::test::chiSquareTest;
using glint::twin::test::sidakSignificance;

namespace {

constexpr int kCosCells = 40;
constexpr int kPhiCells = 8;
constexpr int kSamples = 400000;
constexpr int kAnisotropies = 7; // rows of henyeyGreensteinSamplingMatchesPhase_data

// The phase function integrated over cosTheta in [a, b] and a whole turn, by the midpoint rule
// (fine enough for the forward peak of g = 0.95, about 0.001 wide in cosTheta).
double phaseIntegral(float g, double a, double b) {
    const int steps = int(std::ceil((b - a) * 20000.0));
    double sum = 0.0;
    for (int i = 0; i < steps; ++i) sum += henyeyGreenstein(float(a + (i + 0.5) * (b - a) / steps), g);
    return sum * (b - a) / steps * 2.0 * M_PI;
}

// Optical depth by the midpoint rule on the density itself (double precision).
double numericDepth(vec4 fog, vec3 origin, vec3 direction, double t) {
    constexpr int steps = 20000;
    double sum = 0.0;
    for (int i = 0; i < steps; ++i) {
        const double y = double(origin.y) + (i + 0.5) * t / steps * double(direction.y);
        sum += double(fog.x) * std::exp(-double(fog.y) * (y - double(fog.z)));
    }
    return sum * t / steps;
}

} // namespace

class TestTwinMedia : public QObject {
    Q_OBJECT

private slots:
    void henyeyGreensteinSamplingMatchesPhase_data() {
        QTest::addColumn<float>("g");
        for (float g : {-0.9f, -0.4f, -0.0005f, 0.0f, 0.2f, 0.7f, 0.95f}) QTest::newRow(qPrintable(QString("g=%1").arg(g))) << g;
    }

    // 400k samples around an oblique travel direction, binned by (cos theta, phi) in the frame of
    // that direction: chi-square p-value above the Sidak-corrected 1 % over all rows; the phase
    // integrates to 1 within 1e-4; every sample's pdf is the phase function of its angle within 1e-3.
    void henyeyGreensteinSamplingMatchesPhase() {
        QFETCH(float, g);
        const double total = phaseIntegral(g, -1.0, 1.0);
        QVERIFY2(std::abs(total - 1.0) < 1e-4, qPrintable(QString("integral %1").arg(total)));
        const vec3 travel = normalize(vec3(0.3f, -0.5f, 0.8f));
        const Frame frame = frameFromNormal(travel);
        std::mt19937 random(1234u);
        std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
        std::vector<double> observed(kCosCells * kPhiCells, 0.0);
        for (int i = 0; i < kSamples; ++i) {
            float pdf = 0.0f;
            const vec3 w = sampleHenyeyGreenstein(travel, g, vec2(uniform(random), uniform(random)), pdf);
            const vec3 local = localFromWorld(frame, w);
            QVERIFY2(std::abs(length(w) - 1.0f) < 1e-4f, "not a unit direction");
            const float expectedPdf = henyeyGreenstein(local.z, g);
            // At g = 0.95 the phase changes by 1e3 per unit of cosine near its peak: a float
            // rounding of the angle (1e-7) moves the pdf by 1e-4 of itself.
            QVERIFY2(std::abs(pdf - expectedPdf) <= 1e-3f * expectedPdf, qPrintable(QString("pdf %1 vs %2").arg(pdf).arg(expectedPdf)));
            double phi = std::atan2(double(local.y), double(local.x));
            if (phi < 0.0) phi += 2.0 * M_PI;
            const int c = std::min(int((double(local.z) + 1.0) / 2.0 * kCosCells), kCosCells - 1);
            const int p = std::min(int(phi / (2.0 * M_PI) * kPhiCells), kPhiCells - 1);
            observed[std::size_t(c * kPhiCells + p)] += 1.0;
        }
        std::vector<double> expected(observed.size());
        for (int c = 0; c < kCosCells; ++c)
            for (int p = 0; p < kPhiCells; ++p)
                expected[std::size_t(c * kPhiCells + p)] = kSamples * phaseIntegral(g, -1.0 + 2.0 * c / kCosCells, -1.0 + 2.0 * (c + 1) / kCosCells) / kPhiCells;
        const auto result = chiSquareTest(observed, expected);
        qInfo("%s: %s", QTest::currentDataTag(), result.message.c_str());
        QVERIFY2(result.pValue > sidakSignificance(0.01, kAnisotropies), result.message.c_str());
    }

    // Along rays up, down, level and nearly level (where the closed form switches to its series),
    // through fogs homogeneous and falling fast: closed form within 1e-4 (relative) of the numerical
    // integral, and fogDistanceAtDepth(fogOpticalDepth(t)) within 1e-4 of t.
    void fogOpticalDepthMatchesIntegralAndInverts() {
        const float never = 3.0e38f;
        for (const vec4 fog : {vec4(0.3f, 0.0f, 0.0f, 0.0f), vec4(0.3f, 0.4f, 1.0f, 0.0f), vec4(2.0f, 3.0f, -0.5f, 0.0f)}) {
            for (const vec3 direction : {normalize(vec3(0.2f, 1.0f, 0.1f)), normalize(vec3(0.5f, -0.7f, 0.1f)), vec3(1.0f, 0.0f, 0.0f),
                                         normalize(vec3(1.0f, 2e-5f, 0.0f)), normalize(vec3(1.0f, -3e-4f, 0.0f))}) {
                for (const float t : {1e-3f, 0.4f, 3.0f, 12.0f}) {
                    const vec3 origin(0.5f, 0.25f, -1.0f);
                    const double closed = fogOpticalDepth(fog, origin, direction, t);
                    const double numeric = numericDepth(fog, origin, direction, t);
                    const QString where = QString("fog (%1, %2, %3), direction y %4, t %5").arg(fog.x).arg(fog.y).arg(fog.z).arg(direction.y).arg(t);
                    QVERIFY2(std::abs(closed - numeric) <= 1e-4 * numeric, qPrintable(where + QString(": %1 vs %2").arg(closed).arg(numeric)));
                    // Where exp(-a t) is below about 1e-3, the float depth no longer tells t apart.
                    if (fog.y * direction.y * t > 5.0f) continue;
                    const float back = fogDistanceAtDepth(fog, origin, direction, float(closed), never);
                    QVERIFY2(std::abs(back - t) <= 1e-4f * t, qPrintable(where + QString(": inverse %1").arg(back)));
                }
            }
        }
    }

    // A ray climbing out of a falling fog sees a finite depth, density(origin) / (falloff x dy):
    // a deeper target is never reached. Looking down, or level through a homogeneous fog, the
    // depth to "infinity" is infinite and the transmittance 0.
    void fogDepthToInfinity() {
        const float never = 3.0e38f;
        const vec4 fog(0.5f, 0.8f, 0.0f, 0.0f);
        const vec3 origin(0.0f, 1.0f, 0.0f);
        const vec3 up = normalize(vec3(0.0f, 1.0f, 1.0f));
        const double escape = 0.5 * std::exp(-0.8) / (0.8 * double(up.y));
        QVERIFY(std::abs(fogOpticalDepth(fog, origin, up, never) - escape) < 1e-5 * escape);
        QCOMPARE(fogDistanceAtDepth(fog, origin, up, float(escape * 1.01), never), never);
        QVERIFY(fogDistanceAtDepth(fog, origin, up, float(escape * 0.99), never) < 100.0f);
        QCOMPARE(std::exp(-fogOpticalDepth(fog, origin, -up, never)), 0.0f);
        QCOMPARE(std::exp(-fogOpticalDepth(vec4(0.5f, 0.0f, 0.0f, 0.0f), origin, vec3(1.0f, 0.0f, 0.0f), never)), 0.0f);
    }
};

QTEST_GUILESS_MAIN(TestTwinMedia)
#include "test_twin_media.moc"
