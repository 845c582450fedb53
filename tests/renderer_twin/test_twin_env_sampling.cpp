// Environment importance sampling: the CPU-built CDF table read through the shared GLSL sampler.
// Sampled directions follow environmentDirectionPdf (chi-square over the image's pixels), the pdf
// integrates to 1 over the sphere, and the orientation is docs/UNITS.md's (u = 0.25 faces -Z).
#include "bilinear_map_read.h"
#include "chi_square.h"
#include "renderer/cpu_twin/env_sampling.h"
#include "renderer/cpu_twin/glsl_twin.h"

#include <QtTest>

#include <algorithm>
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

    // One bright pixel on black. The map is read bilinearly, so its light reaches into the
    // neighbouring pixels, and sampling must go there too: the light-sampling estimate of the map's
    // luminance (read / pdf) is right (every lit pixel here stands above the map's mean, which the
    // table leaves to BSDF sampling), and bounded: a corner neighbour, weighted 1/64 of the bright
    // pixel less that mean, reads at most 1/4 of it (at its corner), so no sample reaches 17 times
    // the estimate. With the table weighting each pixel by itself alone, the neighbours were never
    // sampled: the estimate came to 9/16 of the luminance (the rest was left to BSDF sampling), and
    // a sampler with a few such neighbours far from any bright pixel gave 40-fold outliers on real
    // maps.
    void theMapIsSampledAsItIsRead() {
        const int width = 64, height = 32, samples = 100000;
        std::vector<float> rgb(std::size_t(width * height * 3), 0.0f);
        const int brightX = 20, brightY = 12;
        for (int c = 0; c < 3; ++c) rgb[std::size_t((brightY * width + brightX) * 3 + c)] = 100.0f;
        auto table = buildEnvironmentSamplingTable(width, height, rgb);
        sampler2D s = samplerOf(table);
        // The bilinear reconstruction keeps each pixel's integral; sin(theta) is nearly constant over
        // the few pixels it spreads to, so the luminance over the sphere is the pixel's value times
        // the solid angle of its row's pixels.
        const double thetaTop = M_PI * brightY / height, thetaBottom = M_PI * (brightY + 1) / height;
        const double expected = 100.0 * 2.0 * M_PI / width * (std::cos(thetaTop) - std::cos(thetaBottom));
        Rng rng = rngStart(uvec2(5u, 7u), 0u, 0u);
        double sum = 0.0, largest = 0.0;
        for (int i = 0; i < samples; ++i) {
            float pdf;
            vec3 d = sampleEnvironmentDirection(s, ivec2(width, height), rand2(rng), pdf);
            if (!(pdf > 0.0f)) continue;
            const vec2 uv = equirectFromDirection(d);
            const double estimate = glint::test::bilinearMapRead(rgb, width, height, uv.x, uv.y, {0.2126, 0.7152, 0.0722}) / pdf;
            sum += estimate;
            largest = std::max(largest, estimate);
        }
        const double mean = sum / samples;
        QVERIFY2(std::abs(mean / expected - 1.0) < 0.02, qPrintable(QString("estimate %1 of %2").arg(mean).arg(expected)));
        QVERIFY2(largest < 17.0 * mean, qPrintable(QString("largest sample %1 times the mean").arg(largest / mean)));
    }

    // MIS compensation: pixels no brighter than the map's mean are left to BSDF sampling (pdf 0),
    // the rest is sampled in proportion to what stands above the mean. A sky of luminance 1 with a
    // sun of 1000 in one pixel: every sample goes to the sun and its eight neighbours.
    void theMapsMeanIsLeftToBsdfSampling() {
        const int width = 64, height = 32;
        std::vector<float> rgb(std::size_t(width * height * 3), 1.0f);
        for (int c = 0; c < 3; ++c) rgb[std::size_t((8 * width + 40) * 3 + c)] = 1000.0f;
        auto table = buildEnvironmentSamplingTable(width, height, rgb);
        sampler2D s = samplerOf(table);
        QCOMPARE(environmentDirectionPdf(s, ivec2(width, height), directionFromEquirect(vec2(0.1f, 0.7f))), 0.0f);
        Rng rng = rngStart(uvec2(3u, 1u), 0u, 0u);
        for (int i = 0; i < 2000; ++i) {
            float pdf;
            vec2 uv = equirectFromDirection(sampleEnvironmentDirection(s, ivec2(width, height), rand2(rng), pdf));
            const int x = int(uv.x * width), y = int(uv.y * height);
            QVERIFY2(pdf > 0.0f && std::abs(x - 40) <= 1 && std::abs(y - 8) <= 1, qPrintable(QString("sample in pixel %1, %2").arg(x).arg(y)));
        }
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
