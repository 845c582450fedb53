#pragma once
// What one exported image is: the render request and the metadata written with it, planned
// exactly as `glint render` plans the same settings (size, spp, configuration, seed, camera,
// AOVs, time, frame), so that an export from the editor equals the command line's file, pixel
// for pixel and byte for byte apart from the render-time metadata (the export test checks it).
#include "editor/export/export_settings.h"
#include "renderer/offline_render.h"
#include "renderer/output/image_files.h"
#include "renderer/output/render_plan.h"
#include "scene/core/scene.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace glint::editor {

struct ExportFrame {
    std::optional<int> frame;
    std::optional<double> time;
    std::filesystem::path out;
    renderer::RenderRequest request;
    renderer::ImageMetadata metadata; // sealed (settingsHash); version and render time are added on write
};

// The frames of an export, in order (one for a still). Throws std::runtime_error for an unknown
// configuration and std::invalid_argument for a bad frame range or a pattern without '#'.
std::vector<ExportFrame> planExport(const Scene& scene, const ExportSettings& settings);

// Frame k's time: timeline start + k / fps.
double exportFrameTime(const Scene& scene, const ExportSettings& settings, int frame);
// "shot_####.exr" with frame 7 -> "shot_0007.exr" (at least as many digits as '#').
std::filesystem::path framePath(const std::filesystem::path& pattern, int frame);
using renderer::formatNumber; // the shortest locale-independent decimal form, as the command line writes

} // namespace glint::editor
