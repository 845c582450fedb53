// The disocclusion spike: in the first 8 frames of a chunk (history starts at the path's first frame,
// as a render or export that starts mid-animation does) a fast camera uncovers the back wall behind
// the glossy Cornell box's tall block and brings the short block in. Full's mean error along a moving
// path was far below the raw 1-spp error while its worst frames, where history had just restarted,
// kept the raw frame's outliers; and a sunlit room panned fast, whose first frame (filtered from one
// sample) is its worst (docs/DENOISING.md, failure mode 9). Per-frame relMSE of Full and raw 1 spp
// against per-frame converged references; the scenes are tests/data/reconstruction/cornell_fast_pan
// and room_fast_pan (glTF + project file). GLINT_SPIKE_SIZE, GLINT_SPIKE_FRAMES and
// GLINT_SPIKE_REFERENCE_SPP override the test's 64x64, 12 frames and 64 spp (docs: 128, 24, 128 or
// 256), GLINT_SPIKE_SCENE the scene (any file with an animated camera);
// GLINT_RECONSTRUCTION_DUMP=DIR writes the frames.
#include "renderer/frame_renderer.h"
#include "renderer/gl/headless_context.h"
#include "scene/io/scene_io.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace glint;

namespace {

int fromEnvironment(const char* name, int fallback) {
    const char* value = std::getenv(name);
    return value && *value ? std::max(1, std::atoi(value)) : fallback;
}

// relMSE of docs/CLI.md over RGB.
double relMse(const std::vector<float>& image, const std::vector<float>& reference) {
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t p = 0; p * 4 < image.size(); ++p)
        for (std::size_t c = 0; c < 3; ++c) {
            const double x = image[p * 4 + c], r = reference[p * 4 + c];
            sum += (x - r) * (x - r) / (r * r + 0.01);
            ++count;
        }
    return count ? sum / static_cast<double>(count) : 0.0;
}

void dump(const std::vector<float>& radiance, int size, const std::string& name) {
    const char* folder = std::getenv("GLINT_RECONSTRUCTION_DUMP");
    if (!folder) return;
    std::FILE* f = std::fopen((std::string(folder) + "/" + name + ".ppm").c_str(), "wb");
    if (!f) return;
    std::fprintf(f, "P6 %d %d 255\n", size, size);
    for (std::size_t i = 0; i < radiance.size(); i += 4)
        for (std::size_t c = 0; c < 3; ++c) {
            const double v = std::max(0.0, double(radiance[i + c]));
            std::fputc(static_cast<int>(std::lround(std::pow(v / (1.0 + v), 1.0 / 2.2) * 255.0)), f);
        }
    std::fclose(f);
}

// Full's worst frame relative to the raw 1-spp error of that frame, and the ratio of the means.
struct Spike {
    double worstRatio = 0.0;
    int worstFrame = -1;
    double meanRatio = 0.0;
};

// Full, raw 1 spp (a fresh seed each frame) and a converged reference along the scene's animation,
// frame by frame from its first (history starts there), each frame's relMSE printed.
Spike measure(const char* name) {
    const int size = fromEnvironment("GLINT_SPIKE_SIZE", 64);
    const int count = fromEnvironment("GLINT_SPIKE_FRAMES", 12);
    const int referenceSpp = fromEnvironment("GLINT_SPIKE_REFERENCE_SPP", 64);
    const char* file = std::getenv("GLINT_SPIKE_SCENE");
    const Scene scene = loadScene(file && *file ? std::string(file) : std::string(GLINT_TEST_DATA_DIR "/reconstruction/") + name).scene;
    const double fps = 24.0;

    gl::HeadlessContext context;
    renderer::FrameSettings base;
    base.width = size;
    base.height = size;
    base.bounces = 4;
    base.tonemapper = Tonemapper::None;
    const auto rendererFor = [&](renderer::Configuration configuration, int spp, std::uint32_t seed) {
        auto frames = std::make_unique<renderer::FrameRenderer>();
        renderer::FrameSettings s = base;
        s.configuration = configuration;
        s.spp = spp;
        s.seed = seed;
        frames->setSettings(s);
        frames->setScene(scene);
        frames->useSceneCamera();
        return frames;
    };
    auto full = rendererFor(renderer::Configuration::Full, 0, 0);
    auto reference = rendererFor(renderer::Configuration::Accumulate, referenceSpp, 0x9e3779b9u);
    auto raw = rendererFor(renderer::Configuration::Accumulate, 1, 0);

    double fullSum = 0.0, rawSum = 0.0;
    Spike spike;
    for (int k = 0; k < count; ++k) {
        const double time = k / fps;
        full->setTime(time);
        full->renderFrame();
        const auto image = full->readImages().radiance;
        reference->setTime(time);
        reference->renderFrame();
        const auto converged = reference->readImages().radiance;
        renderer::FrameSettings rawSettings = raw->settings();
        rawSettings.seed = static_cast<std::uint32_t>(k); // fresh noise each frame, as a real-time frame has
        raw->setSettings(rawSettings);
        raw->setTime(time);
        raw->renderFrame();
        const double e = relMse(image, converged);
        const double r = relMse(raw->readImages().radiance, converged);
        fullSum += e;
        rawSum += r;
        if (e / r > spike.worstRatio) spike.worstRatio = e / r, spike.worstFrame = k;
        qInfo("frame %2d: Full %.4f, raw 1 spp %.4f, ratio %.3f", k, e, r, e / r);
        dump(image, size, std::string(name) + "_full_" + std::to_string(k));
        dump(converged, size, std::string(name) + "_reference_" + std::to_string(k));
    }
    spike.meanRatio = fullSum / rawSum;
    qInfo("%s, %dx%d, %d frames: worst frame %d at %.3fx raw; mean Full %.4f, raw %.4f (%.3fx)", name, size, size,
          count, spike.worstFrame, spike.worstRatio, fullSum / count, rawSum / count, spike.meanRatio);
    return spike;
}

} // namespace

class TestDisocclusionSpike : public QObject {
    Q_OBJECT

private slots:
    // Tolerance: Full's worst frame below 0.25x the raw 1-spp error of that frame (the issue asks
    // for 0.5x; before the outlier limit at restart this scene's worst was 0.42x, frame 9, and its
    // first frame 0.38x; now 0.09x), and Full's mean error below 0.05x raw's (was 0.090x, now 0.025x).
    void fastCameraUncoversWall() {
        const Spike spike = measure("cornell_fast_pan.glint.json");
        QVERIFY(spike.worstRatio < 0.25);
        QVERIFY(spike.meanRatio < 0.05);
    }

    // The sunlit test room (room_fast_pan: the camera passes the red box 15 cm a frame): its worst
    // frame is its first, filtered from one sample. Tolerance: below 0.4x raw (0.43x before the
    // first frame's looser luminance stop, now 0.36x), the mean not above 0.21x (0.199x before, now
    // 0.194x).
    void sunlitFirstFrame() {
        const Spike spike = measure("room_fast_pan.glint.json");
        QVERIFY(spike.worstRatio < 0.4);
        QVERIFY(spike.meanRatio < 0.21);
    }
};

QTEST_GUILESS_MAIN(TestDisocclusionSpike)
#include "test_disocclusion_spike.moc"
