#pragma once
// What one exported image is: the render request and the metadata written with it, planned
// exactly as `glint render` plans the same settings (size, spp, configuration, seed, camera,
// AOVs, time, frame), so that an export from the editor equals the command line's file, pixel
// for pixel and byte for byte apart from the render-time metadata (the export test checks it).
#include "renderer/offline_render.h"
#include "renderer/output/image_files.h"
#include "scene/core/scene.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace glint::editor {

struct ExportSettings {
    std::filesystem::path sceneFile;  // the document's file: metadata and the environment folder
    std::filesystem::path out;        // a still's file, or an animation's pattern with one '#' run
    int width = 640;
    int height = 360;
    int spp = 64;
    std::string configuration = "accumulate";
    std::uint32_t seed = 0;
    std::string camera;               // empty: the project's active camera
    std::string aovs = "all";         // EXR layers, as --aovs
    std::optional<double> time;       // a still at this time (as --time); unset: the scene as it is
    bool animation = false;
    int firstFrame = 0;
    int lastFrame = 0;
    int fpsNumerator = 24;
    int fpsDenominator = 1;
};

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
// The shortest locale-independent decimal form, as the command line writes numbers.
std::string formatNumber(double value);

} // namespace glint::editor
