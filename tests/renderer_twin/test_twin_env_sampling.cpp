// Environment importance sampling: the CPU-built CDF table read through the shared GLSL sampler.
// Sampled directions follow environmentDirectionPdf (chi-square over the image's pixels), the pdf
// integrates to 1 over the sphere, and the orientation is docs/UNITS.md's (u = 0.25 faces -Z).
#include "chi_square.h"
#include "renderer/cpu_twin/env_sampling.h"
#include "renderer/cpu_twin/glsl_twin.h"

#include <QtTest>

#include <cmath>
#include <vector>

using namespace glint::twin;
using glint::twin::test::chiSquareTest;

namespace {

sampler2D samplerOf(const EnvironmentSamplingTable& t) { return sampler2D{t.tableWidth, t.tableHeight, t.cdf.data()}; }

// A deterministic image with a smooth gradient, a dark band and one bright pixel.
std::vector<float> testImage(int width, int height) {
    std::vector<float> rgb(std::size_t(width * height * 3));
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            float value = 0.2f + float(x) / float(width) + (y == height / 2 ? 0.0f : float(y) / float(height));
            if (x >= width / 2 && x < width / 2 + 3) value = 0.0f;
            if (x == 3 && y == 2) value = 40.0f;
            for (int c = 0; c < 3; ++c) rgb[std::size_t((y * width + x) * 3 + c)] = value * (c == 1 ? 1.0f : 0.5f);
        }
    }
    return rgb;
}

// A black image except the pixels whose centres lie within `radius` pixels of (u, v).
std::vector<float> spotImage(int width, int height, float u, float v) {
    std::vector<float> rgb(std::size_t(width * height * 3), 0.0f);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            float du = (float(x) + 0.5f) / float(width) - u;
            float dv = (float(y) + 0.5f) / float(height) - v;
            if (std::abs(du) < 1.0f / float(width) && std::abs(dv) < 1.0f / float(height))
                for (int c = 0; c < 3; ++c) rgb[std::size_t((y * width + x) * 3 + c)] = 5.0f;
        }
    }
    return rgb;
}

vec3 meanSampledDirection(const EnvironmentSamplingTable& table, int samples) {
    sampler2D s = samplerOf(table);
    Rng rng = rngStart(uvec2(4u, 4u), 0u, 0u);
    vec3 sum(0.0f);
    for (int i = 0; i < samples; ++i) {
        float pdf;
        sum += sampleEnvironmentDirection(s, ivec2(table.imageWidth, table.imageHeight), rand2(rng), pdf);
    }
    return normalize(sum);
}

} // namespace

class TwinEnvSamplingTest : public QObject {
    Q_OBJECT
private slots:
    void tableRowsAreCdfs() {
        auto t = buildEnvironmentSamplingTable(16, 8, testImage(16, 8));
        QCOMPARE(t.tableWidth, 17);
        QCOMPARE(t.tableHeight, 9);
        for (int row = 0; row < 8; ++row) {
            QCOMPARE(t.cdf[std::size_t(row * 17)], 0.0f);
            QCOMPARE(t.cdf[std::size_t(row * 17 + 16)], 1.0f);
        }
        QCOMPARE(t.cdf[std::size_t(8 * 17 + 8)], 1.0f); // marginal over 8 rows
    }

    void mismatchedPixelsAreRejected() {
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, buildEnvironmentSamplingTable(4, 2, std::vector<float>(23)));
    }

    void directionMapsRoundTrip() {
        for (vec2 uv : {vec2(0.1f, 0.3f), vec2(0.25f, 0.5f), vec2(0.9f, 0.8f)}) {
            vec2 back = equirectFromDirection(directionFromEquirect(uv));
            QVERIFY(std::abs(back.x - uv.x) < 1e-5f && std::abs(back.y - uv.y) < 1e-5f);
        }
        // docs/UNITS.md: d = (0, 0, -1) -> u = 0.25; image centre faces +X; +Y is the top row.
        QVERIFY(std::abs(equirectFromDirection(vec3(0.0f, 0.0f, -1.0f)).x - 0.25f) < 1e-6f);
        QVERIFY(std::abs(equirectFromDirection(vec3(1.0f, 0.0f, 0.0f)).x - 0.5f) < 1e-6f);
        QVERIFY(equirectFromDirection(vec3(0.0f, 1.0f, 0.0f)).y < 1e-6f);
    }

    // A bright spot at u = 0.25 (v = 0.5) is sampled around -Z, one at u = 0.5 around +X, one near
    // the top row around +Y.
    void brightSpotsAreSampledInTheirDirection() {
        QVERIFY(dot(meanSampledDirection(buildEnvironmentSamplingTable(64, 32, spotImage(64, 32, 0.25f, 0.5f)), 2000),
                    vec3(0.0f, 0.0f, -1.0f)) > 0.995f);
        QVERIFY(dot(meanSampledDirection(buildEnvironmentSamplingTable(64, 32, spotImage(64, 32, 0.5f, 0.5f)), 2000),
                    vec3(1.0f, 0.0f, 0.0f)) > 0.995f);
        QVERIFY(meanSampledDirection(buildEnvironmentSamplingTable(64, 32, spotImage(64, 32, 0.5f, 1.0f / 32.0f)), 2000).y >
                0.98f);
    }

    // Chi-square over pixels: sample counts against the pdf integrated over each pixel's solid angle
    // (an 8 x 8 midpoint rule in (u, v) with dw = 2 pi^2 sin(theta) du dv); the integrals sum to 1.
    void samplesFollowPdf() {
        const int width = 16, height = 8, samples = 200000;
        auto table = buildEnvironmentSamplingTable(width, height, testImage(width, height));
        sampler2D s = samplerOf(table);
        ivec2 size(width, height);
        std::vector<double> observed(std::size_t(width * height), 0.0);
        Rng rng = rngStart(uvec2(9u, 9u), 0u, 0u);
        int mismatches = 0;
        for (int i = 0; i < samples; ++i) {
            float pdf;
            vec3 d = sampleEnvironmentDirection(s, size, rand2(rng), pdf);
            // A sample on a pixel border may round into its neighbour when mapped back: rare.
            mismatches += std::abs(pdf - environmentDirectionPdf(s, size, d)) <= 1e-3f * pdf ? 0 : 1;
            vec2 uv = equirectFromDirection(d);
            int x = std::min(int(uv.x * width), width - 1), y = std::min(int(uv.y * height), height - 1);
            observed[std::size_t(y * width + x)] += 1.0;
        }
        QVERIFY2(mismatches <= samples / 100000, qPrintable(QString("%1 pdf mismatches").arg(mismatches)));
        std::vector<double> expected(observed.size(), 0.0);
        double total = 0.0;
        const int sub = 8;
        for (int y = 0; y < height * sub; ++y) {
            for (int x = 0; x < width * sub; ++x) {
                vec2 uv((float(x) + 0.5f) / float(width * sub), (float(y) + 0.5f) / float(height * sub));
                double dw = 2.0 * M_PI * M_PI * std::sin(M_PI * uv.y) / double(width * sub * height * sub);
                double p = environmentDirectionPdf(s, size, directionFromEquirect(uv)) * dw;
                expected[std::size_t((y / sub) * width + x / sub)] += p * samples;
                total += p;
            }
        }
        QVERIFY2(std::abs(total - 1.0) < 1e-3, qPrintable(QString("pdf integrates to %1").arg(total)));
        auto result = chiSquareTest(observed, expected);
        QVERIFY2(result.pValue > 0.01, result.message.c_str());
    }

    // A black environment still has a valid table: uniform on the sphere, pdf 1 / 4pi.
    void blackImageSamplesUniformly() {
        auto table = buildEnvironmentSamplingTable(32, 16, std::vector<float>(32 * 16 * 3, 0.0f));
        sampler2D s = samplerOf(table);
        float pdf = environmentDirectionPdf(s, ivec2(32, 16), normalize(vec3(0.3f, 0.2f, -0.5f)));
        QVERIFY2(std::abs(pdf * 4.0f * PI - 1.0f) < 0.02f, qPrintable(QString::number(pdf * 4.0f * PI)));
    }
};

QTEST_APPLESS_MAIN(TwinEnvSamplingTest)
#include "test_twin_env_sampling.moc"
