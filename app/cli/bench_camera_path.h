#pragma once
// `glint bench` along the scene's camera path: each configuration renders the animation's frames
// (camera path and node animations, at the project fps) from a fresh history, timed per frame, and
// is compared with converged per-frame references at frames 1, 2, 4, ... and the last. This is the
// motion series beside the still-camera one: reprojection, disocclusion and lag show here.
#include "speed_accuracy_chart.h"

#include "renderer/configuration.h"
#include "renderer/frame_renderer.h"
#include "scene/core/scene.h"

#include <CLI/CLI.hpp>

#include <functional>
#include <vector>

namespace glint::cli {

struct PathBenchOptions {
    bool enabled = true;       // --no-path turns it off
    int frames = 0;            // 0: every frame of the animation's default range
    int referenceSpp = 256;    // per-frame references (one per sampled frame)
};

// One configuration along the path; the same figures as a still-camera bench row. relmse and ssim
// are means over the sampled frames; the curve holds (cumulative ms, relMSE) at each of them.
struct PathBenchRow {
    renderer::Configuration config{};
    int spp = 1, bounces = 0, frames = 0;
    double msMedian = 0, msP10 = 0, msP90 = 0, relmse = 0, ssim = 0;
    bench::ChartCurve curve;
};

void addPathBenchOptions(CLI::App& bench, PathBenchOptions& options);

// Whether the scene has a camera path or animation to follow (frame_timing.h hasAnimation).
bool wantsPathBench(const PathBenchOptions& options, const Scene& scene);

// `settingsFor` gives the still bench's frame settings of a configuration (size, spp, bounces,
// seed). `frames` must hold the scene and follow the benched camera; its time is left at the end.
std::vector<PathBenchRow> runPathBench(renderer::FrameRenderer& frames, const Scene& scene, const PathBenchOptions& options,
                                       const std::vector<renderer::Configuration>& configs,
                                       const std::function<renderer::FrameSettings(renderer::Configuration)>& settingsFor);

} // namespace glint::cli
