#include "scene_defaults.h"

#include "scene/core/default_view.h"
#include "scene/core/light_sources.h"

#include <algorithm>

namespace glint::cli {
namespace {

bool hasCamera(const Scene& scene, const std::string& name) {
    return std::any_of(scene.nodes().begin(), scene.nodes().end(), [&](const auto& entry) {
        const Node& node = entry.second;
        return node.get<Camera>() && (name.empty() || node.name == name);
    });
}

} // namespace

Size outputSize(const CommonRenderOptions& options, const Scene& scene) {
    return options.size.value_or(Size{scene.settings.render.width, scene.settings.render.height});
}

void completeForRender(LoadResult& loaded, const std::string& file, const std::string& camera, bool envGiven, Size size) {
    Scene& scene = loaded.scene;
    if (!camera.empty()) {
        if (!hasCamera(scene, camera)) throw FileError(file, "no-camera", "no camera named \"" + camera + "\"");
    } else if (!hasCamera(scene, "")) {
        addDefaultView(scene, float(size.width) / float(std::max(1, size.height)));
        loaded.warnings.push_back({file, "no-camera",
                                   "the scene has no camera: rendering from a default view of the whole scene "
                                   "(\"" + std::string(kDefaultViewName) + "\")"});
    }
    if (envGiven) return;
    switch (sceneLighting(scene)) {
    case SceneLighting::None:
        loaded.warnings.push_back({file, "no-light",
                                   "nothing in the scene emits light (no light, emissive material or "
                                   "environment): the image will be black; add a light or pass --env FILE"});
        break;
    case SceneLighting::EmissiveTexturesOnly:
        loaded.warnings.push_back({file, "only-emissive-textures",
                                   "only emissive textures give light (no light, untextured emissive material or "
                                   "environment): most of the image will be dark; add a light or pass --env FILE"});
        break;
    case SceneLighting::Lit: break;
    }
}

} // namespace glint::cli
