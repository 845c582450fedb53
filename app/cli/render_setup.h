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
    // scene, camera, spp, seed, configuration, size, bounces, clamp, env, tonemap, exposureEv;
    // callers add what they vary (time, aovs, frame) and then sealSettings().
    renderer::ImageMetadata metadata;
};

// Locale-independent shortest form ("0.5" under every locale), for metadata.
std::string formatNumber(double value);

// Sets metadata["settingsHash"]: FNV-1a over every entry but the render time and the version, so
// a frame is re-rendered by --resume exactly when something that changes its pixels changed.
void sealSettings(RenderPlan& plan);

// Throws std::runtime_error for settings the renderer cannot honour (e.g. a configuration it lacks).
RenderPlan planRender(const Scene& scene, const std::string& sceneFile, const CommonRenderOptions& options);

} // namespace glint::cli
