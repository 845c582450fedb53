#include "bench_camera_path.h"

#include "frame_timing.h"
#include "image_metrics.h"
#include "percentile.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>

namespace glint::cli {
namespace {

using Clock = std::chrono::steady_clock;

// Frames compared with a reference: 1, 2, 4, ... and the last (references cost far more than frames).
bool sampled(int frame, int last) { return frame == last || (frame > 0 && (frame & (frame - 1)) == 0); }

struct PathFrame {
    double time = 0.0;
    std::vector<float> reference; // empty where the frame is not sampled
};

std::vector<PathFrame> pathFrames(const Scene& scene, const PathBenchOptions& o) {
    const Fps fps{scene.settings.timeline.fpsNumerator, scene.settings.timeline.fpsDenominator};
    const FrameRange range = defaultFrameRange(scene, fps);
    const int count = o.frames > 0 ? std::min(o.frames, range.count()) : range.count();
    std::vector<PathFrame> frames;
    for (int k = 0; k < count; ++k) frames.push_back({frameTime(scene, fps, range.first + k), {}});
    return frames;
}

// Converged images at the sampled frames, with another seed than the runs.
void renderReferences(renderer::FrameRenderer& frames, std::vector<PathFrame>& path, const PathBenchOptions& o,
                      const renderer::FrameSettings& base) {
    renderer::FrameSettings s = base;
    s.configuration = renderer::Configuration::Reference;
    s.spp = o.referenceSpp;
    s.seed = base.seed + 0x9e3779b9u;
    frames.setSettings(s);
    const int last = static_cast<int>(path.size()) - 1;
    for (int k = 0; k <= last; ++k) {
        if (!sampled(k, last)) continue;
        frames.setTime(path[static_cast<std::size_t>(k)].time);
        frames.resetHistory();
        frames.renderFrame();
        path[static_cast<std::size_t>(k)].reference = frames.readImages().radiance;
    }
}

PathBenchRow runConfiguration(renderer::FrameRenderer& frames, const std::vector<PathFrame>& path,
                              const renderer::FrameSettings& s) {
    frames.setSettings(s);
    frames.setTime(path.front().time);
    frames.resetHistory();
    frames.renderFrame(); // warm-up: shader compilation is not a frame time
    glFinish();
    frames.resetHistory(); // history starts at the path's first frame, as a chunk does
    PathBenchRow row;
    row.config = s.configuration;
    row.spp = s.spp > 0 ? s.spp : renderer::traitsOf(s.configuration).sppPerFrame;
    row.bounces = renderer::traitsOf(s.configuration).gi ? s.bounces : 0;
    row.frames = static_cast<int>(path.size());
    row.curve.name = std::string(renderer::configurationName(s.configuration));
    std::vector<double> ms;
    double total = 0.0;
    int compared = 0;
    for (const PathFrame& frame : path) {
        frames.setTime(frame.time); // the pose upload is not part of the frame time
        glFinish();
        const auto start = Clock::now();
        frames.renderFrame();
        glFinish();
        ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
        total += ms.back();
        if (frame.reference.empty()) continue;
        const renderer::FrameImages images = frames.readImages();
        const double error = bench::relMse(images.radiance, frame.reference);
        row.relmse += error;
        row.ssim += bench::ssim(images.radiance, frame.reference, images.width, images.height);
        row.curve.points.push_back({total, error});
        ++compared;
    }
    row.relmse /= std::max(compared, 1);
    row.ssim /= std::max(compared, 1);
    row.msMedian = bench::percentile(ms, 0.5);
    row.msP10 = bench::percentile(ms, 0.1);
    row.msP90 = bench::percentile(ms, 0.9);
    return row;
}

} // namespace

void addPathBenchOptions(CLI::App& bench, PathBenchOptions& options) {
    bench.add_flag_function("--no-path", [&options](std::int64_t) { options.enabled = false; },
                            "Skip the run along the scene's camera path (default: run it when the scene has a camera "
                            "path or animation; writes bench_path.csv, bench_path.json, speed_accuracy_path.png/.svg)");
    bench.add_option("--path-frames", options.frames,
                     "Frames along the camera path, from its first (default: the animation's frames at the project fps)")
        ->check(CLI::Range(1, 100000));
    bench.add_option("--path-reference-spp", options.referenceSpp,
                     "Samples per pixel of each per-frame reference along the path (default: 256)")
        ->check(CLI::Range(1, 1 << 20));
}

bool wantsPathBench(const PathBenchOptions& options, const Scene& scene) { return options.enabled && hasAnimation(scene); }

std::vector<PathBenchRow> runPathBench(renderer::FrameRenderer& frames, const Scene& scene, const PathBenchOptions& options,
                                       const std::vector<renderer::Configuration>& configs,
                                       const std::function<renderer::FrameSettings(renderer::Configuration)>& settingsFor) {
    std::vector<PathFrame> path = pathFrames(scene, options);
    std::vector<PathBenchRow> rows;
    if (path.empty()) return rows;
    std::fprintf(stderr, "glint: camera path: %d frames, references at %d spp\n", static_cast<int>(path.size()),
                 options.referenceSpp);
    renderReferences(frames, path, options, settingsFor(renderer::Configuration::Reference));
    for (const renderer::Configuration c : configs) {
        std::fprintf(stderr, "glint: %s along the path\n", std::string(renderer::configurationName(c)).c_str());
        rows.push_back(runConfiguration(frames, path, settingsFor(c)));
    }
    return rows;
}

} // namespace glint::cli
