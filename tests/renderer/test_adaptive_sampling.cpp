// Adaptive sampling (renderer/passes/adaptive_sampling.h): pixels stop taking samples once their
// mean has converged, by 8x8 tiles. Cornell box (bundled), 40x40, 4 bounces, seed 3, noise threshold
// 0.2, tests from 8 samples on, at most 48: measured, 384 pixels stop at the first test, the others
// at five later tests, 64 take every sample.
// - A stopped pixel holds exactly what a render without adaptive sampling holds after as many
//   samples: radiance and variance bit for bit (a stopped pixel takes no more samples, a sampling
//   one takes the same samples as without stops). Every pixel is checked against the uniform
//   render at its own count.
// - Pixels stop by whole 8x8 tiles, and a tile's stop depends on its own pixels alone: a region (not
//   aligned to tiles) stops the same pixels at the same counts as the whole image.
// - The goal Mean (threshold 0.02, same render; measured, tiles stop at 12 to 48 samples) stops each
//   tile at the first test where one more sample would lower its relMSE by less than threshold^2,
//   from the tile's own pixels; it too keeps the uniform mean of each pixel's count, and a region
//   stops what the whole image stops.
// - An image whose every pixel converged ends the render: 8 samples of 1000 are taken.
// - The render passes of stopped pixels still sum to the beauty.
#include "render_scene.h"
#include "scene_builder.h"

#include "renderer/passes/adaptive_sampling.h"
#include "scene/io/scene_io.h"

#include <QTest>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <set>

using namespace glint;

Q_DECLARE_METATYPE(glint::AdaptiveGoal)

namespace {

constexpr int kSize = 40;
constexpr int kMinSpp = 8;
constexpr int kSpp = 48;
constexpr float kThreshold = 0.2f;
constexpr float kMeanThreshold = 0.02f; // AdaptiveGoal::Mean's, for about the same spread of counts

Scene cornell() {
    return loadScene(std::filesystem::path(GLINT_RESOURCES_DIR) / "scenes" / "cornell_box" / "cornell_box.gltf").scene;
}

renderer::RenderRequest adaptiveRequest(AdaptiveGoal goal = AdaptiveGoal::Even) {
    renderer::RenderRequest request = test::stillRequest(kSize, kSpp, 3, 4);
    request.adaptive = {.threshold = goal == AdaptiveGoal::Mean ? kMeanThreshold : kThreshold, .minSamples = kMinSpp, .goal = goal};
    return request;
}

// AdaptiveGoal::Mean's measure of the 8x8 tile at (tx, ty), from a uniform render's mean and
// sample variance after n samples: sqrt(a) / n (shaders/passes/adaptive_converged.glsl).
double meanGoalMeasure(const std::vector<float>& radiance, const std::vector<float>& variance, int tx, int ty, int n) {
    double sum = 0.0;
    for (int y = ty * 8; y < ty * 8 + 8; ++y)
        for (int x = tx * 8; x < tx * 8 + 8; ++x) {
            const std::size_t i = std::size_t(y) * kSize + std::size_t(x);
            for (std::size_t c = 0; c < 3; ++c) {
                const double mean = radiance[i * 4 + c];
                sum += double(variance[i * 3 + c]) / (mean * mean + 0.01) / 3.0;
            }
        }
    return std::sqrt(sum / 64.0) / n;
}

struct UniformMean {
    std::vector<float> radiance;
    std::vector<float> variance;
};

// The running mean without adaptive sampling, read back after each sample count in `counts`.
std::map<int, UniformMean> uniformMeans(const Scene& scene, const renderer::RenderRequest& adaptive, const std::set<int>& counts) {
    renderer::RenderRequest request = adaptive;
    request.adaptive = {};
    renderer::FrameRenderer frames;
    frames.setSettings(renderer::frameSettingsFor(request, 1));
    frames.setCamera(renderer::resolveCamera(scene, "", request.width, request.height));
    frames.setScene(scene);
    frames.resetHistory();
    std::map<int, UniformMean> means;
    for (int n = 1; n <= *counts.rbegin(); ++n) {
        frames.renderFrame();
        if (!counts.count(n)) continue;
        renderer::FrameImages images = frames.readImages();
        means[n] = {std::move(images.radiance), std::move(images.variance)};
    }
    return means;
}

bool sameBits(const float* a, const float* b, std::size_t count) { return std::memcmp(a, b, count * sizeof(float)) == 0; }

} // namespace

class TestAdaptiveSampling : public QObject {
    Q_OBJECT
    static void goals() {
        QTest::addColumn<AdaptiveGoal>("goal");
        QTest::newRow("even") << AdaptiveGoal::Even;
        QTest::newRow("mean") << AdaptiveGoal::Mean;
    }
private slots:
    void minimumSamplesAndTestSchedule() {
        QCOMPARE(renderer::adaptiveMinSamples({.threshold = 0.01f}, 4096), 64); // Cycles' automatic 16 / 0.01^0.3
        QCOMPARE(renderer::adaptiveMinSamples({.threshold = 0.005f, .goal = AdaptiveGoal::Mean}, 4096), 16); // Mean's automatic
        QCOMPARE(renderer::adaptiveMinSamples({.threshold = 0.005f, .goal = AdaptiveGoal::Mean}, 10), 10);
        QCOMPARE(renderer::adaptiveMinSamples({.threshold = 0.01f, .minSamples = 100}, 4096), 100);
        QCOMPARE(renderer::adaptiveMinSamples({.threshold = 0.01f}, 32), 32);                  // at most spp
        QCOMPARE(renderer::adaptiveMinSamples({.threshold = 0.5f, .minSamples = 1}, 4096), 2);   // one sample has no variance
        QVERIFY(!renderer::adaptiveTestDue(7, 8));
        QVERIFY(renderer::adaptiveTestDue(8, 8));
        QVERIFY(!renderer::adaptiveTestDue(10, 8));
        QVERIFY(renderer::adaptiveTestDue(12, 8));
    }

    void stoppedPixelsHoldTheUniformMeanOfTheirCount_data() { goals(); }
    void stoppedPixelsHoldTheUniformMeanOfTheirCount() {
        QFETCH(AdaptiveGoal, goal);
        const Scene scene = cornell();
        renderer::OfflineRenderer renderer;
        const renderer::RenderOutput adaptive = renderer.render(scene, adaptiveRequest(goal));
        QCOMPARE(adaptive.sampleCounts.size(), std::size_t(kSize * kSize));
        std::set<int> counts;
        std::map<int, int> pixelsAt;
        for (const float c : adaptive.sampleCounts) {
            counts.insert(int(c));
            ++pixelsAt[int(c)];
        }
        QVERIFY2(pixelsAt.begin()->first <= kMinSpp + 4, "the easiest tiles stop at the first tests");
        QVERIFY2(pixelsAt[kSpp] > 0, "the noisiest tiles take every sample");
        for (const auto& [c, n] : pixelsAt) QVERIFY2(n % 64 == 0, "whole 8x8 tiles stop together");
        QVERIFY2(counts.size() > 3, "pixels stop at several tests between");
        for (const int c : counts) QVERIFY(c >= kMinSpp && c <= kSpp && (c - kMinSpp) % 4 == 0);

        const auto means = uniformMeans(scene, adaptiveRequest(goal), counts);
        int checked = 0;
        for (std::size_t i = 0; i < adaptive.sampleCounts.size(); ++i) {
            const UniformMean& uniform = means.at(int(adaptive.sampleCounts[i]));
            if (!sameBits(&adaptive.radiance[i * 4], &uniform.radiance[i * 4], 4) ||
                !sameBits(&adaptive.variance[i * 3], &uniform.variance[i * 3], 3))
                QFAIL(qPrintable(QString("pixel %1 (%2 samples): radiance %3 against %4 without adaptive sampling")
                                     .arg(i).arg(adaptive.sampleCounts[i]).arg(adaptive.radiance[i * 4]).arg(uniform.radiance[i * 4])));
            ++checked;
        }
        QCOMPARE(checked, kSize * kSize);
        QCOMPARE(adaptive.timings.samplesTaken, kSpp);
    }

    void aRegionStopsThePixelsTheWholeImageStops_data() { goals(); }
    void aRegionStopsThePixelsTheWholeImageStops() {
        QFETCH(AdaptiveGoal, goal);
        const Scene scene = cornell();
        renderer::OfflineRenderer renderer;
        const renderer::RenderOutput whole = renderer.render(scene, adaptiveRequest(goal));
        renderer::RenderRequest request = adaptiveRequest(goal);
        request.region = renderer::ImageWindow{10, 6, 17, 23};
        const renderer::RenderOutput region = renderer.render(scene, request);
        std::set<float> counts;
        for (int y = 6; y < 6 + 23; ++y)
            for (int x = 10; x < 10 + 17; ++x) {
                const std::size_t i = std::size_t(y) * kSize + std::size_t(x);
                QCOMPARE(region.sampleCounts[i], whole.sampleCounts[i]);
                QVERIFY(sameBits(&region.radiance[i * 4], &whole.radiance[i * 4], 4));
                counts.insert(region.sampleCounts[i]);
            }
        QVERIFY2(counts.size() > 2, "the region holds pixels that stopped at different tests");
    }

    void meanGoalStopsEachTileAtItsFirstTestBelowTheThreshold() {
        const Scene scene = cornell();
        renderer::OfflineRenderer renderer;
        const renderer::RenderOutput adaptive = renderer.render(scene, adaptiveRequest(AdaptiveGoal::Mean));
        std::set<int> tests;
        for (int n = kMinSpp; n <= kSpp; n += 4) tests.insert(n);
        const auto means = uniformMeans(scene, adaptiveRequest(AdaptiveGoal::Mean), tests);
        std::set<int> stops;
        int decided = 0;
        for (int ty = 0; ty < kSize / 8; ++ty)
            for (int tx = 0; tx < kSize / 8; ++tx) {
                const int stopped = int(adaptive.sampleCounts[std::size_t(ty * 8) * kSize + std::size_t(tx * 8)]);
                stops.insert(stopped);
                bool ambiguous = false;
                int expected = kSpp;
                for (const int n : tests) {
                    const UniformMean& m = means.at(n);
                    const double measure = meanGoalMeasure(m.radiance, m.variance, tx, ty, n);
                    // GPU and CPU sum in different orders: a measure this close to the threshold may go either way.
                    ambiguous = ambiguous || std::abs(measure / kMeanThreshold - 1.0) < 1e-4;
                    if (measure < kMeanThreshold) {
                        expected = n;
                        break;
                    }
                }
                if (ambiguous) continue;
                QVERIFY2(stopped == expected, qPrintable(QString("tile (%1, %2) stopped at %3 samples, the rule says %4")
                                                              .arg(tx).arg(ty).arg(stopped).arg(expected)));
                ++decided;
            }
        QVERIFY2(decided >= 24, "at most one of the 25 tiles is too close to the threshold to decide");
        QVERIFY2(stops.size() > 3, "tiles stop at several tests");
        QVERIFY2(stops.count(kSpp) == 1, "the noisiest tiles take every sample");
    }

    void aConvergedImageEndsTheRender() {
        Scene scene; // nothing but a uniform environment: every sample of a pixel is the same
        scene.settings.environment.color = {0.5f, 0.25f, 0.125f};
        test::addPerspectiveCamera(scene, {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, 0.8f);
        renderer::RenderRequest request = test::stillRequest(16, 1000, 0, 4);
        request.adaptive = {.threshold = 0.01f, .minSamples = kMinSpp};
        int lastDone = 0;
        int lastTotal = 0;
        int calls = 0;
        request.progress = [&](int done, int total) { lastDone = done; lastTotal = total; ++calls; };
        renderer::OfflineRenderer renderer;
        const renderer::RenderOutput out = renderer.render(scene, request);
        QCOMPARE(out.timings.samplesTaken, kMinSpp);
        QCOMPARE(calls, kMinSpp);
        QCOMPARE(lastDone, 1000); // the progress ends at 100 %
        QCOMPARE(lastTotal, 1000);
        for (const float c : out.sampleCounts) QCOMPARE(c, float(kMinSpp));
        QCOMPARE(out.radiance[0], 0.5f);
        QCOMPARE(out.radiance[2], 0.125f);
    }

    void renderPassesOfStoppedPixelsSumToTheBeauty() {
        renderer::RenderRequest request = adaptiveRequest();
        request.renderPasses = true;
        renderer::OfflineRenderer renderer;
        const renderer::RenderOutput out = renderer.render(cornell(), request);
        int stopped = 0;
        for (std::size_t i = 0; i < out.sampleCounts.size(); ++i) {
            stopped += out.sampleCounts[i] < float(kSpp) ? 1 : 0;
            for (std::size_t c = 0; c < 3; ++c) {
                double sum = 0.0;
                for (const auto& pass : out.lightPasses) sum += double(pass[i * 3 + c]);
                const double beauty = double(out.radiance[i * 4 + c]);
                QVERIFY2(std::abs(sum - beauty) <= 2e-6 * std::abs(beauty) + 1e-7,
                         qPrintable(QString("pixel %1: passes %2, beauty %3").arg(i).arg(sum).arg(beauty)));
            }
        }
        QVERIFY(stopped > kSize * kSize / 4);
    }
};

QTEST_GUILESS_MAIN(TestAdaptiveSampling)
#include "test_adaptive_sampling.moc"
