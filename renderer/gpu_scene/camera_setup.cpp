#include "renderer/gpu_scene/camera_setup.h"

#include "scene/core/default_view.h"

#include <cmath>
#include <optional>
#include <stdexcept>

namespace glint::renderer {
namespace {

std::optional<NodeId> findCamera(const Scene& scene, const std::string& name) {
    const auto isCamera = [&](NodeId id) { return scene.contains(id) && scene.at(id).get<Camera>() != nullptr; };
    if (!name.empty()) {
        for (const NodeId id : scene.depthFirst())
            if (isCamera(id) && scene.at(id).name == name) return id;
        return std::nullopt;
    }
    if (const NodeId id = defaultCamera(scene); id.valid()) return id;
    return std::nullopt;
}

} // namespace

CameraSetup resolveCamera(const Scene& scene, const std::string& name, int width, int height) {
    const auto id = findCamera(scene, name);
    if (!id) throw std::runtime_error(name.empty() ? "the scene has no camera" : "no camera named \"" + name + "\"");
    const Camera& camera = *scene.at(*id).get<Camera>();
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    CameraSetup setup;
    setup.node = *id;
    setup.worldFromCamera = scene.worldFromNode(*id);
    setup.orthographic = camera.projection == Projection::Orthographic;
    if (setup.orthographic) {
        setup.halfExtent = {camera.ymag * aspect, camera.ymag};
    } else {
        const float tanHalf = std::tan(0.5f * camera.yfov);
        setup.halfExtent = {tanHalf * aspect, tanHalf};
    }
    setup.lensRadius = camera.lensRadius;
    setup.focusDistance = camera.focusDistance;
    setup.exposure = camera.exposure;
    return setup;
}

} // namespace glint::renderer
