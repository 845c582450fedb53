#pragma once
// One image of `glint render`: plan, render (polling for SIGINT/SIGTERM between samples), write.
// Stills and every frame of an animation go through here, so both get the same metadata and hash.
#include "render_options.h"
#include "render_setup.h"
#include "report.h"
#include "stop_signal.h"

#include "renderer/offline_render.h"
#include "scene/core/scene.h"

#include <filesystem>

namespace glint::cli {

// Thrown out of a render when a stop signal arrived: the frame is discarded, nothing is written.
struct RenderStopped {};

struct FrameJob {
    const Scene* scene = nullptr; // already posed at `time`
    std::filesystem::path out;
    std::optional<double> time;
    std::optional<int> frame;     // animation frames: the number, and the seed offset
    std::optional<Fps> fps;
    bool history = false;         // a frame of a history chunk: one seed for the chunk, K and W hashed
    WarningsOnce* warnings = nullptr; // prints the renderer's warnings once per run (none: not printed)
};

// The plan of one image with its sealed settings hash (before rendering: --resume compares it).
RenderPlan planImage(const RenderOptions& options, const FrameJob& job);

// Renders and writes atomically; throws RenderStopped, FileError or std::runtime_error.
void renderImage(renderer::OfflineRenderer& gpu, const RenderOptions& options, const FrameJob& job, RenderPlan plan,
                 const StopSignal& stop, bool sampleProgress);

} // namespace glint::cli
