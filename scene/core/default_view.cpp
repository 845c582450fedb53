#include "scene/core/default_view.h"

#include "scene/core/scene_bounds.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace glint {
namespace {

constexpr float kMargin = 1.1f;
constexpr float kEmptySceneDistance = 5.0f;

// Distance from the centre at which a sphere of `radius` fills the narrower half-angle.
float framingDistance(float radius, float yfov, float aspect) {
    const float halfY = 0.5f * yfov;
    const float halfX = std::atan(std::tan(halfY) * std::max(aspect, 1e-3f));
    return kMargin * std::max(radius, 1e-3f) / std::sin(std::min(halfX, halfY));
}

} // namespace

// From the front and a little above: a flat front view hides the top of most assets.
glm::vec3 defaultViewFromCentre() { return glm::normalize(glm::vec3(0.0f, 0.35f, 1.0f)); }

NodeId defaultCamera(const Scene& scene) {
    const auto isCamera = [&](NodeId id) { return scene.contains(id) && scene.at(id).get<Camera>() != nullptr; };
    if (isCamera(scene.settings.activeCamera)) return scene.settings.activeCamera;
    for (const NodeId id : scene.depthFirst())
        if (isCamera(id)) return id;
    return {};
}

NodeId addDefaultView(Scene& scene, float aspect) {
    Camera camera;
    const Bounds bounds = worldBounds(scene);
    glm::vec3 centre(0.0f);
    float distance = kEmptySceneDistance;
    if (!bounds.empty()) {
        centre = bounds.centre();
        distance = framingDistance(0.5f * glm::length(bounds.max - bounds.min), camera.yfov, aspect);
    }
    camera.focusDistance = distance;
    Node node;
    node.name = std::string(kDefaultViewName);
    const glm::vec3 fromCentre = defaultViewFromCentre();
    node.local.translation = centre + fromCentre * distance;
    node.local.rotation = glm::quatLookAt(-fromCentre, glm::vec3(0.0f, 1.0f, 0.0f));
    node.component = camera;
    const NodeId id = scene.addNode(std::move(node));
    scene.settings.activeCamera = id;
    return id;
}

} // namespace glint
