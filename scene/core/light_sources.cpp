#include "scene/core/light_sources.h"

#include "scene/core/visibility.h"

#include <algorithm>

namespace glint {
namespace {

bool emissive(const Scene& scene, MaterialId id) {
    const Material* material = scene.materials.find(id);
    if (!material) return false;
    const glm::vec3 radiance = material->emissiveFactor * material->emissiveStrength;
    return std::max({radiance.x, radiance.y, radiance.z}) > 0.0f;
}

bool emits(const Scene& scene, const Node& node) {
    if (const auto* light = node.get<Light>())
        return light->intensity > 0.0f && std::max({light->color.x, light->color.y, light->color.z}) > 0.0f;
    if (const auto* shape = node.get<Shape>()) return emissive(scene, shape->material);
    if (const auto* instance = node.get<MeshInstance>())
        if (const Mesh* mesh = scene.meshes.find(instance->mesh))
            return std::any_of(mesh->primitives.begin(), mesh->primitives.end(),
                               [&](const Primitive& p) { return emissive(scene, p.material); });
    return false;
}

} // namespace

bool environmentEmits(const Environment& environment) {
    if (environment.intensity <= 0.0f) return false;
    if (!environment.file.empty()) return true;
    return std::max({environment.color.x, environment.color.y, environment.color.z}) > 0.0f;
}

bool hasLightSource(const Scene& scene) {
    if (environmentEmits(scene.settings.environment)) return true;
    for (const NodeId id : scene.depthFirst()) {
        const Node& node = *scene.node(id);
        if (visibleInWorld(scene, node) && emits(scene, node)) return true;
    }
    return false;
}

} // namespace glint
