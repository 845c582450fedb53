// Known answers of the BSDF: Fresnel at normal incidence, Snell's law, total internal reflection,
// thin walls, KHR_materials_specular's factor 0, reciprocity, the multiple-scattering table; and
// no NaN, Inf or negative value for random materials and directions, grazing ones included.
#include "renderer/cpu_twin/glsl_twin.h"

#include <QtTest>

using namespace glint::twin;

namespace {

SurfaceMaterial glass(float roughness, bool thinWalled) {
    SurfaceMaterial m = defaultSurfaceMaterial();
    m.roughness = roughness;
    m.transmission = 1.0f;
    m.thinWalled = thinWalled;
    return m;
}

vec3 atAngle(float cosTheta) { return vec3(std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta)), 0.0f, cosTheta); }

// Fraction of samples that reflect (stay on wo's side).
float reflectedFraction(const SurfaceMaterial& m, vec3 wo, int samples) {
    Rng rng = rngStart(uvec2(3u, 3u), 0u, 0u);
    int reflected = 0;
    for (int i = 0; i < samples; ++i) {
        BsdfSample s;
        if (bsdfSample(m, wo, rand3(rng), s) && s.wi.z * wo.z > 0.0f) ++reflected;
    }
    return float(reflected) / float(samples);
}

} // namespace

class TwinBsdfKnownTest : public QObject {
    Q_OBJECT
private slots:
    void fresnelOfGlassAtNormalIncidenceIsFourPercent() {
        QVERIFY(std::abs(fresnelDielectric(1.0f, 1.5f) - 0.04f) < 1e-6f);
        QVERIFY(std::abs(dielectricF0(1.5f, vec3(1.0f)).x - 0.04f) < 1e-6f);
        QVERIFY(std::abs(reflectedFraction(glass(0.0f, false), vec3(0.0f, 0.0f, 1.0f), 100000) - 0.04f) < 0.003f);
    }

    // 45 degrees into glass of IOR 1.5: sin(theta_t) = sin(45) / 1.5, and the weight carries 1 / eta^2.
    void smoothRefractionObeysSnell() {
        vec3 wo = normalize(vec3(1.0f, 0.0f, 1.0f));
        BsdfSample s;
        QVERIFY(bsdfSample(glass(0.0f, false), wo, vec3(0.99f, 0.5f, 0.5f), s));
        QVERIFY((s.lobe & LOBE_TRANSMISSION) != 0u && (s.lobe & LOBE_SPECULAR) != 0u);
        float sinT = std::sqrt(s.wi.x * s.wi.x + s.wi.y * s.wi.y);
        QVERIFY(std::abs(sinT - std::sqrt(0.5f) / 1.5f) < 1e-5f);
        QVERIFY(s.wi.z < 0.0f && s.wi.x < 0.0f);
        QVERIFY(std::abs(s.eta - 1.5f) < 1e-6f);
        QVERIFY(std::abs(s.weight.x - 1.0f / 2.25f) < 1e-5f);
    }

    // From inside glass beyond the critical angle (41.8 degrees) everything reflects.
    void totalInternalReflectionBeyondCriticalAngle() {
        vec3 inside = -atAngle(std::cos(0.8f)); // 45.8 degrees from -Z
        QCOMPARE(reflectedFraction(glass(0.0f, false), inside, 1000), 1.0f);
        vec3 below = -atAngle(std::cos(0.6f)); // 34.4 degrees: some light leaves
        QVERIFY(reflectedFraction(glass(0.0f, false), below, 1000) < 0.5f);
    }

    void thinWallTransmitsStraightThrough() {
        vec3 wo = normalize(vec3(0.3f, -0.2f, 0.9f));
        BsdfSample s;
        QVERIFY(bsdfSample(glass(0.0f, true), wo, vec3(0.99f, 0.5f, 0.5f), s));
        QVERIFY(length(s.wi + wo) < 1e-6f);
        QCOMPARE(s.eta, 1.0f);
    }

    void specularFactorZeroIsPureLambert() {
        SurfaceMaterial m = defaultSurfaceMaterial();
        m.baseColor = vec3(0.2f, 0.5f, 0.8f);
        m.roughness = 0.3f;
        m.specularFactor = 0.0f;
        vec3 wo = atAngle(0.4f);
        vec3 wi = normalize(vec3(-0.5f, 0.1f, 0.7f));
        float pdf;
        vec3 f = bsdfEval(m, wo, wi, pdf);
        vec3 lambert = m.baseColor * wi.z / PI;
        QVERIFY(length(f - lambert) < 1e-6f);
        QVERIFY(std::abs(pdf - wi.z / PI) < 1e-6f);
    }

    // f(wo, wi) = f(wi, wo) for a metal once the multiple-scattering scale, which depends on the
    // direction it is evaluated from (Turquin 2019), is divided out.
    void metalIsReciprocalUpToEnergyScale() {
        Rng rng = rngStart(uvec2(8u, 1u), 0u, 0u);
        for (int i = 0; i < 2000; ++i) {
            SurfaceMaterial m = defaultSurfaceMaterial();
            m.metallic = 1.0f;
            m.roughness = 0.05f + 0.95f * rand1(rng);
            m.baseColor = vec3(0.9f, 0.5f, 0.2f);
            vec3 wo = cosineHemisphere(rand2(rng));
            vec3 wi = cosineHemisphere(rand2(rng));
            float pdf;
            vec3 forward = bsdfEval(m, wo, wi, pdf) / wi.z / ggxMultipleScatteringScale(m.baseColor, wo.z, m.roughness);
            vec3 backward = bsdfEval(m, wi, wo, pdf) / wo.z / ggxMultipleScatteringScale(m.baseColor, wi.z, m.roughness);
            QVERIFY2(length(forward - backward) <= 1e-4f * length(forward) + 1e-6f,
                     qPrintable(QString("sample %1: %2 vs %3").arg(i).arg(forward.x).arg(backward.x)));
        }
    }

    // The multiple-scattering tables (ggx_energy.glsl) agree with a fresh integration of E(mu, r)
    // and of its Fresnel-weighted twin B(mu, r), within 0.01.
    void compensationTablesMatchIntegration() {
        for (float roughness : {0.1f, 0.2f, 0.5f, 0.8f, 1.0f}) {
            for (float mu : {0.1f, 0.45f, 1.0f}) {
                vec3 wo(std::sqrt(1.0f - mu * mu), 0.0f, mu);
                float alpha = ggxAlphaFromRoughness(roughness);
                double e = 0.0, b = 0.0;
                const int n = 128;
                for (int i = 0; i < n; ++i) {
                    for (int j = 0; j < n; ++j) {
                        vec3 h = sampleGgxVisibleNormal(wo, alpha, vec2((float(i) + 0.5f) / n, (float(j) + 0.5f) / n));
                        vec3 wi = reflect(-wo, h);
                        if (wi.z <= 0.0f) continue;
                        double w = ggxG2(wo, wi, alpha) / ggxG1(wo, alpha) / (n * n);
                        e += w;
                        b += w * std::pow(1.0 - double(dot(wo, h)), 5.0);
                    }
                }
                QString where = QString("r %1 mu %2: ").arg(roughness).arg(mu);
                QVERIFY2(std::abs(ggxDirectionalAlbedo(mu, roughness) - e) < 0.01,
                         qPrintable(where + QString("E table %1, integral %2").arg(ggxDirectionalAlbedo(mu, roughness)).arg(e)));
                QVERIFY2(std::abs(ggxFresnelAlbedo(mu, roughness) - b) < 0.01,
                         qPrintable(where + QString("B table %1, integral %2").arg(ggxFresnelAlbedo(mu, roughness)).arg(b)));
            }
        }
    }

    // Random materials (roughness 0 to 1, IOR 1 to 3, any mixture) and directions from both sides,
    // grazing included: every sample and evaluation is finite and non-negative.
    void randomInputsGiveFiniteValues() {
        Rng rng = rngStart(uvec2(6u, 6u), 0u, 0u);
        int bad = 0;
        for (int i = 0; i < 200000; ++i) {
            vec4 a = rand4(rng);
            vec4 b = rand4(rng);
            SurfaceMaterial m = defaultSurfaceMaterial();
            m.metallic = a.x < 0.3f ? 0.0f : a.x;
            m.roughness = a.y < 0.2f ? 0.0f : a.y;
            m.transmission = a.z < 0.4f ? 0.0f : 1.0f;
            m.ior = 1.0f + 2.0f * a.w;
            m.thinWalled = b.x < 0.5f;
            m.specularFactor = b.y;
            vec3 wo = uniformSphere(vec2(b.z, b.w));
            if (i % 7 == 0) wo = normalize(vec3(wo.x, wo.y, wo.z * 1e-6f)); // grazing
            BsdfSample s;
            bool sampled = bsdfSample(m, wo, rand3(rng), s);
            float pdf;
            vec3 f = bsdfEval(m, wo, uniformSphere(rand2(rng)), pdf);
            bool ok = isFiniteVec3(f) && isFiniteFloat(pdf) && pdf >= 0.0f && f.x >= 0.0f && f.y >= 0.0f && f.z >= 0.0f;
            if (sampled) {
                ok = ok && isFiniteVec3(s.weight) && isFiniteFloat(s.pdf) && s.pdf > 0.0f && s.weight.x >= 0.0f &&
                     std::abs(length(s.wi) - 1.0f) < 1e-3f;
            }
            bad += ok ? 0 : 1;
        }
        QCOMPARE(bad, 0);
    }
};

QTEST_APPLESS_MAIN(TwinBsdfKnownTest)
#include "test_twin_bsdf_known.moc"
