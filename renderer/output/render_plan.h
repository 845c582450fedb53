#pragma once
// One place that turns a scene's project settings plus explicit overrides (the command line's
// options, the editor's export dialog) into a render request and the metadata that describes it.
// Both hosts plan through here, so the same settings give the same request, the same EXR header
// and the same settings hash wherever a frame is rendered.
#include "renderer/offline_render.h"
#include "renderer/output/image_files.h"
#include "scene/core/scene.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace glint::renderer {

struct ImageSize {
    int width = 0;
    int height = 0;
};

// Unset fields keep the project's value (docs/CLI.md: --size, --spp, --seed, --bounces, --config,
// --camera, --exposure, --tonemap, --env).
struct RenderOverrides {
    std::optional<ImageSize> size;
    std::optional<int> spp;
    std::uint32_t seed = 0;
    std::optional<int> bounces;
    std::optional<std::string> config;
    std::optional<std::string> camera;
    double exposure = 0.0;              // EV added to the camera's and the project's
    std::optional<std::string> tonemap; // a name of scene/core/tonemapper_names.h
    std::optional<std::string> env;     // an environment image anywhere on disk
    bool requireGpu = false;
    std::optional<float> bloom;         // strength, 0 (off) to 1; unset: the project's
    std::optional<float> bloomRadius;   // fraction of the image height; unset: the project's
    bool bloomLinear = false;           // the EXR's radiance bloomed too
    std::optional<float> shutter;       // motion blur, frames the shutter is open (0 off to 1); unset: the project's
    std::optional<int> sampleBlock;     // pixels per side of the blocks sharing a sample sequence; unset: the project's
    std::optional<float> adaptiveThreshold; // adaptive sampling's noise threshold, 0 (off) to 1; unset: the project's
    std::optional<int> adaptiveMinSpp;      // samples before its first test, 0 = automatic; unset: the project's
    std::optional<std::string> adaptiveGoal; // "even" or "mean" (scene/core/settings.h); unset: the project's
};

struct RenderPlan {
    RenderRequest request;
    // scene, camera, spp, seed, configuration, size, bounces, clamp, env, tonemap, exposureEv;
    // callers add what they vary (time, aovs, frame) and then sealSettings().
    ImageMetadata metadata;
};

// Throws std::runtime_error for settings the renderer cannot honour (an unknown configuration).
RenderPlan planRender(const Scene& scene, const std::filesystem::path& sceneFile, const RenderOverrides& overrides);

// Asks for the EXR's render passes and records them (hashed): "passes" (passListName) and, with
// Vector, "vectorSeconds" (request.motionSeconds: one frame of the project's timeline unless the
// caller set another fps). No passes: nothing changes, so earlier frames keep their settings hash.
void planRenderPasses(RenderPlan& plan, const RenderPasses& passes);

// Sets metadata["settingsHash"]: FNV-1a over every entry but the render time and the version, so
// a frame is re-rendered by --resume exactly when something that changes its pixels changed.
void sealSettings(ImageMetadata& metadata);

// Locale-independent shortest form ("0.5" under every locale), for metadata.
std::string formatNumber(double value);

} // namespace glint::renderer
