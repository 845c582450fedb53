// Lights with extent under multiple importance sampling, on the CPU through the GLSL's C++ twin
// (sampling/sphere_light.glsl, the BSDF, the cone warp): the radiance a surface reflects from a
// sphere lamp or a sun disk, estimated by light sampling alone, by BSDF sampling alone (rays that hit
// the sphere or leave inside the disk's cone) and by both weighted with the power heuristic, as the
// path tracer combines them, must agree within their statistical error.
#include "renderer/cpu_twin/glsl_twin.h"

#include <QTest>

#include <cmath>

using namespace glint::twin;

namespace {

constexpr int kSamples = 1 << 18;

struct Estimate {
    double mean = 0.0;
    double standardError = 0.0;
};

struct Accumulator {
    double sum = 0.0;
    double sumSquares = 0.0;
    void add(double x) {
        sum += x;
        sumSquares += x * x;
    }
    Estimate estimate(int n) const {
        const double mean = sum / n;
        return {mean, std::sqrt(std::max(sumSquares / n - mean * mean, 0.0) / n)};
    }
};

// A cone of directions of uniform radiance seen from the shading point (local frame, normal +Z):
// a sphere lamp (`radius` > 0 at `centre`) or a sun disk around `axis`.
struct ConeLight {
    vec3 axis;
    float oneMinusCos;
    float radiance;
    vec3 centre;  // lamps only
    float radius; // 0: a sun disk
};

ConeLight sphereLamp(vec3 centre, float radius, float intensity) {
    return {normalize(centre), sphereConeOneMinusCos(radius, dot(centre, centre)), sphereLampRadiance(vec3(intensity), radius).x, centre, radius};
}

ConeLight sunDisk(vec3 towardsSun, float halfAngle, float irradiance) {
    const float oneMinusCos = 1.0f - std::cos(halfAngle);
    return {normalize(towardsSun), oneMinusCos, irradiance * conePdfFromOneMinusCos(oneMinusCos), vec3(0.0f), 0.0f};
}

// Whether a BSDF-sampled direction finds the light, as the path tracer's ray would.
bool finds(const ConeLight& light, vec3 wi) {
    if (light.radius > 0.0f) return hitSphereFromOutside(vec3(0.0f), wi, light.centre, light.radius, 1e30f) > 0.0f;
    return dot(wi, light.axis) >= 1.0f - light.oneMinusCos;
}

struct Strategies {
    Estimate light, bsdf, mis;
};

Strategies estimate(const SurfaceMaterial& m, vec3 wo, const ConeLight& light) {
    Rng rng = rngStart(uvec2(17u, 29u), 0u, 5u);
    const Frame cone = frameFromNormal(light.axis);
    const float lightPdf = conePdfFromOneMinusCos(light.oneMinusCos);
    Accumulator onlyLight, onlyBsdf, mis;
    for (int i = 0; i < kSamples; ++i) {
        // Light sampling: a uniform direction in the cone.
        const vec3 wl = worldFromLocal(cone, uniformCone(rand2(rng), 1.0f - light.oneMinusCos));
        float bsdfPdfOfWl;
        const double fl = bsdfEval(m, wo, wl, bsdfPdfOfWl).x;
        const double lightTerm = fl * light.radiance / lightPdf;
        onlyLight.add(lightTerm);
        // BSDF sampling: the sampled direction collects the light where it finds it.
        BsdfSample s;
        double bsdfTerm = 0.0, bsdfWeight = 1.0;
        if (bsdfSample(m, wo, rand3(rng), s) && finds(light, s.wi)) {
            bsdfTerm = double(s.weight.x) * light.radiance;
            if ((s.lobe & LOBE_SPECULAR) == 0u) bsdfWeight = powerHeuristic(s.pdf, lightPdf);
        }
        onlyBsdf.add(bsdfTerm);
        mis.add(lightTerm * powerHeuristic(lightPdf, bsdfPdfOfWl) + bsdfTerm * bsdfWeight);
    }
    return {onlyLight.estimate(kSamples), onlyBsdf.estimate(kSamples), mis.estimate(kSamples)};
}

SurfaceMaterial material(float metallic, float roughness, float transmission) {
    SurfaceMaterial m = defaultSurfaceMaterial();
    m.baseColor = vec3(0.8f);
    m.metallic = metallic;
    m.roughness = roughness;
    m.transmission = transmission;
    return m;
}

bool agree(const Estimate& a, const Estimate& b) {
    return std::abs(a.mean - b.mean) <= 4.0 * std::hypot(a.standardError, b.standardError) + 1e-3 * std::abs(b.mean);
}

} // namespace

class TestLightMisCpu : public QObject {
    Q_OBJECT

private slots:
    // 2^18 samples per strategy, seed key (17, 29). Materials: Lambert (specular 1 layer at roughness
    // 0.5 over it), GGX metal at roughness 0.25 and 0.6, rough glass (0.4). Lights: a lamp of radius
    // 0.5 m at 2 m, 25 degrees off the normal, and a 0.2 rad sun 15 degrees off the mirror direction.
    // Viewed 30 degrees off the normal. Each pair must agree within 4 combined standard errors + 0.1 %.
    void strategiesAgree_data() {
        QTest::addColumn<float>("metallic");
        QTest::addColumn<float>("roughness");
        QTest::addColumn<float>("transmission");
        QTest::addColumn<bool>("sun");
        for (bool sun : {false, true}) {
            const char* light = sun ? "sun" : "lamp";
            QTest::newRow(qPrintable(QString("layered diffuse, %1").arg(light))) << 0.0f << 0.5f << 0.0f << sun;
            QTest::newRow(qPrintable(QString("metal 0.25, %1").arg(light))) << 1.0f << 0.25f << 0.0f << sun;
            QTest::newRow(qPrintable(QString("metal 0.6, %1").arg(light))) << 1.0f << 0.6f << 0.0f << sun;
            QTest::newRow(qPrintable(QString("rough glass 0.4, %1").arg(light))) << 0.0f << 0.4f << 1.0f << sun;
        }
    }
    void strategiesAgree() {
        QFETCH(float, metallic);
        QFETCH(float, roughness);
        QFETCH(float, transmission);
        QFETCH(bool, sun);
        const float viewAngle = 0.5236f; // 30 degrees
        const vec3 wo(std::sin(viewAngle), 0.0f, std::cos(viewAngle));
        const float lampAngle = 0.4363f; // 25 degrees, on the far side of the normal from wo
        const ConeLight light = sun ? sunDisk(vec3(-std::sin(viewAngle + 0.26f), 0.0f, std::cos(viewAngle + 0.26f)), 0.1f, 1.0f)
                                    : sphereLamp(2.0f * vec3(-std::sin(lampAngle), 0.0f, std::cos(lampAngle)), 0.5f, 1.0f);
        const Strategies s = estimate(material(metallic, roughness, transmission), wo, light);
        qInfo("light %.5f +- %.5f, bsdf %.5f +- %.5f, mis %.5f +- %.5f", s.light.mean, s.light.standardError, s.bsdf.mean,
              s.bsdf.standardError, s.mis.mean, s.mis.standardError);
        QVERIFY(s.light.mean > 0.0);
        QVERIFY2(agree(s.bsdf, s.light), "BSDF sampling alone differs from light sampling alone");
        QVERIFY2(agree(s.mis, s.light), "MIS differs from light sampling alone");
        QVERIFY2(agree(s.mis, s.bsdf), "MIS differs from BSDF sampling alone");
    }

    // A perfect mirror (a delta lobe) finds a sun disk only by BSDF sampling: light sampling gives 0
    // and the reflected radiance is the disk's, times Fresnel (base colour 1: exactly 1).
    void mirrorSeesDiskThroughItsDeltaLobe() {
        SurfaceMaterial m = material(1.0f, 0.0f, 0.0f);
        m.baseColor = vec3(1.0f);
        const vec3 wo(std::sin(0.3f), 0.0f, std::cos(0.3f));
        const ConeLight light = sunDisk(vec3(-wo.x, 0.0f, wo.z), 0.05f, 1.0f);
        const Strategies s = estimate(m, wo, light);
        QCOMPARE(s.light.mean, 0.0);
        QVERIFY2(std::abs(s.mis.mean - light.radiance) < 1e-4 * light.radiance,
                 qPrintable(QString("%1 vs %2").arg(s.mis.mean).arg(light.radiance)));
    }
};

QTEST_APPLESS_MAIN(TestLightMisCpu)
#include "test_light_mis_cpu.moc"
