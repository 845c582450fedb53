// The CPU twin of shaders/common/rng.glsl: reference values of pcg4d, uniformity, and that a value
// depends only on its key (pixel, sample, dimension, seed), never on what was drawn before.
#include "renderer/cpu_twin/glsl_twin.h"

#include <QtTest>

#include <vector>

using namespace glint::twin;

class TwinRngTest : public QObject {
    Q_OBJECT
private slots:
    // Reference values from an independent Python implementation of Jarzynski and Olano's pcg4d.
    void pcg4dMatchesReference() {
        QCOMPARE(pcg4d(uvec4(0u, 0u, 0u, 0u)), uvec4(251852841u, 760645481u, 850445371u, 3542436074u));
        QCOMPARE(pcg4d(uvec4(1u, 2u, 3u, 4u)), uvec4(908250390u, 4044648920u, 3775961919u, 45698095u));
        QCOMPARE(pcg4d(uvec4(4294967295u, 7u, 123456u, 99u)),
                 uvec4(2245085791u, 550641447u, 2968346965u, 1944108668u));
    }

    void streamDrawsReferenceValue() {
        Rng r = rngStart(uvec2(3u, 5u), 7u, 11u);
        rand1(r);
        rand1(r);
        QCOMPARE(r.dimension, 2u);
        QCOMPARE(rand1(r), 0.6838541030883789f); // (2937131249 >> 8) / 2^24
    }

    void unitFloatStaysBelowOne() {
        QCOMPARE(unitFloatFromBits(0xffffffffu), 16777215.0f / 16777216.0f);
        QVERIFY(unitFloatFromBits(0xffffffffu) < 1.0f);
        QCOMPARE(unitFloatFromBits(0u), 0.0f);
    }

    // 64 buckets over 2^18 draws from many pixels and dimensions: chi-square within 4.5 sigma of its
    // mean (dof 63, sigma sqrt(126)), mean within 0.002 of 1/2.
    void drawsAreUniform() {
        std::vector<int> buckets(64, 0);
        double sum = 0.0;
        const int n = 1 << 18;
        for (uint pixel = 0; pixel < 4096u; ++pixel) {
            Rng r = rngStart(uvec2(pixel % 64u, pixel / 64u), 3u, 0u);
            for (int d = 0; d < n / 4096; ++d) {
                float x = rand1(r);
                sum += x;
                ++buckets[int(x * 64.0f)];
            }
        }
        double expected = double(n) / 64.0;
        double chi2 = 0.0;
        for (int count : buckets) chi2 += (count - expected) * (count - expected) / expected;
        QVERIFY2(std::abs(chi2 - 63.0) < 4.5 * std::sqrt(126.0), qPrintable(QString("chi2 %1").arg(chi2)));
        QVERIFY(std::abs(sum / n - 0.5) < 0.002);
    }

    // pbrt's ConsistentValues: draw at one pixel, go elsewhere, come back: identical values.
    void sameKeyGivesSameValues() {
        auto draw = [](uvec2 pixel, uint sampleIndex, uint seed) {
            Rng r = rngStart(pixel, sampleIndex, seed);
            std::vector<float> values;
            for (int i = 0; i < 8; ++i) values.push_back(rand1(r));
            vec4 four = rand4(r);
            values.insert(values.end(), {four.x, four.y, four.z, four.w});
            return values;
        };
        std::vector<float> first = draw(uvec2(17u, 4u), 9u, 1u);
        std::vector<float> elsewhere = draw(uvec2(200u, 31u), 2u, 1u);
        QCOMPARE(draw(uvec2(17u, 4u), 9u, 1u), first);
        QVERIFY(elsewhere != first);
        QVERIFY(draw(uvec2(17u, 4u), 9u, 2u) != first); // another seed
        QVERIFY(draw(uvec2(17u, 4u), 10u, 1u) != first); // another sample
    }

    // Neighbouring keys must not give correlated streams: the correlation of the first draw between
    // horizontally adjacent pixels stays within 5 standard errors of 0.
    void neighbouringPixelsAreUncorrelated() {
        const int n = 1 << 16;
        double sxy = 0.0;
        for (int i = 0; i < n; ++i) {
            Rng a = rngStart(uvec2(uint(i), 7u), 0u, 0u);
            Rng b = rngStart(uvec2(uint(i) + 1u, 7u), 0u, 0u);
            sxy += (rand1(a) - 0.5) * (rand1(b) - 0.5);
        }
        double correlation = sxy / n * 12.0;
        QVERIFY2(std::abs(correlation) < 5.0 / std::sqrt(double(n)), qPrintable(QString::number(correlation)));
    }
};

QTEST_APPLESS_MAIN(TwinRngTest)
#include "test_twin_rng.moc"
