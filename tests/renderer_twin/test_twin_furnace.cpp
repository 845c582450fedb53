// White furnace per BSDF on the CPU: the directional albedo E(wo) = integral of f |cos| over the
// sphere, estimated as the mean sample weight (refraction weights times eta^2, undoing the
// radiance scaling that makes transport non-symmetric). Nothing may create energy: E <= 1 + 1 %;
// white opaque materials, compensated for multiple scattering, keep at least 98.5 %.
// The table it prints is docs/MATERIALS.md's furnace table.
#include "renderer/cpu_twin/glsl_twin.h"

#include <QtTest>

using namespace glint::twin;

namespace {

constexpr int kSamples = 100000;

SurfaceMaterial whiteMaterial(float metallic, float roughness, float transmission, bool thinWalled) {
    SurfaceMaterial m = defaultSurfaceMaterial();
    m.metallic = metallic;
    m.roughness = roughness;
    m.transmission = transmission;
    m.thinWalled = thinWalled;
    return m;
}

vec3 incident(float cosTheta) { return vec3(std::sqrt(1.0f - cosTheta * cosTheta), 0.0f, cosTheta); }

struct Estimate {
    double mean = 0.0;
    double standardError = 0.0;
};

// Mean of the first channel of the weight (the materials here are grey).
Estimate directionalAlbedo(const SurfaceMaterial& m, vec3 wo, uint key) {
    Rng rng = rngStart(uvec2(key, 2u), 0u, 7u);
    double sum = 0.0, sumSquares = 0.0;
    for (int i = 0; i < kSamples; ++i) {
        BsdfSample s;
        if (!bsdfSample(m, wo, rand3(rng), s)) continue;
        double w = double(s.weight.x) * double(s.eta) * double(s.eta);
        sum += w;
        sumSquares += w * w;
    }
    double mean = sum / kSamples;
    double variance = std::max(0.0, sumSquares / kSamples - mean * mean);
    return {mean, std::sqrt(variance / kSamples)};
}

} // namespace

Q_DECLARE_METATYPE(SurfaceMaterial)

class TwinFurnaceTest : public QObject {
    Q_OBJECT
private slots:
    // Lambert with albedo 1 through bsdfEval and uniform hemisphere directions (independent of the
    // BSDF's own sampler): 1 within 0.5 %; albedo 0.5 gives 0.5.
    void lambertAlbedoIsItsBaseColor() {
        for (float albedo : {1.0f, 0.5f}) {
            SurfaceMaterial m = whiteMaterial(0.0f, 1.0f, 0.0f, true);
            m.specularFactor = 0.0f;
            m.baseColor = vec3(albedo);
            Rng rng = rngStart(uvec2(1u, 1u), 0u, 0u);
            double sum = 0.0;
            const int n = 400000;
            for (int i = 0; i < n; ++i) {
                vec3 wi = uniformSphere(rand2(rng));
                float pdf;
                sum += double(bsdfEval(m, incident(0.6f), wi, pdf).x) / double(uniformSpherePdf());
            }
            QVERIFY2(std::abs(sum / n - albedo) < 0.005 * albedo, qPrintable(QString::number(sum / n)));
        }
    }

    void noEnergyGain_data() {
        QTest::addColumn<SurfaceMaterial>("m");
        for (float roughness : {0.0f, 0.1f, 0.3f, 0.6f, 1.0f}) {
            QTest::newRow(qPrintable(QString("metal r%1").arg(roughness))) << whiteMaterial(1.0f, roughness, 0.0f, true);
            QTest::newRow(qPrintable(QString("plastic r%1").arg(roughness))) << whiteMaterial(0.0f, roughness, 0.0f, true);
            QTest::newRow(qPrintable(QString("glass r%1").arg(roughness))) << whiteMaterial(0.0f, roughness, 1.0f, false);
            QTest::newRow(qPrintable(QString("thin glass r%1").arg(roughness))) << whiteMaterial(0.0f, roughness, 1.0f, true);
        }
    }

    // E(wo) from outside (cos 1, 0.5, 0.1) and, for refracting glass, from inside as well.
    void noEnergyGain() {
        QFETCH(SurfaceMaterial, m);
        QString line = QTest::currentDataTag();
        bool refracting = m.transmission > 0.0f && !m.thinWalled;
        uint key = qHash(QByteArray(QTest::currentDataTag()));
        for (float cosWo : {1.0f, 0.5f, 0.1f, -1.0f, -0.5f, -0.1f}) {
            if (cosWo < 0.0f && !refracting) continue;
            Estimate e = directionalAlbedo(m, incident(cosWo), key);
            line += QString(" | %1").arg(e.mean, 0, 'f', 4);
            QVERIFY2(e.mean <= 1.01 + 3.0 * e.standardError,
                     qPrintable(QString("E(cos %1) = %2 +- %3").arg(cosWo).arg(e.mean).arg(e.standardError)));
            // White metal and layered dielectric are compensated for multiple scattering: nothing may
            // be lost either.
            if (m.transmission == 0.0f)
                QVERIFY2(e.mean >= 0.985, qPrintable(QString("opaque E(cos %1) = %2").arg(cosWo).arg(e.mean)));
        }
        qInfo("%s", qPrintable(line));
    }
};

QTEST_APPLESS_MAIN(TwinFurnaceTest)
#include "test_twin_furnace.moc"
