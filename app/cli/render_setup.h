#pragma once
// Turns a scene's project settings plus command-line overrides into one render request, and the
// metadata that describes it (written into EXR headers; its hash identifies the settings).
#include "common_options.h"

#include "renderer/offline_render.h"
#include "renderer/output/image_files.h"
#include "scene/core/scene.h"

#include <string>

namespace glint::cli {

struct RenderPlan {
    renderer::RenderRequest request;
    renderer::ImageMetadata metadata; // scene, camera, spp, seed, config, settingsHash
};

// Locale-independent shortest form ("0.5" under every locale), for metadata.
std::string formatNumber(double value);

// Throws std::runtime_error for settings the renderer cannot honour (e.g. a configuration it lacks).
RenderPlan planRender(const Scene& scene, const std::string& sceneFile, const CommonRenderOptions& options);

} // namespace glint::cli
