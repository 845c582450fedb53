#include "scene/core/light_sources.h"

#include "scene/core/visibility.h"

#include <algorithm>

namespace glint {
namespace {

SceneLighting emission(const Scene& scene, MaterialId id) {
    const Material* material = scene.materials.find(id);
    if (!material) return SceneLighting::None;
    const glm::vec3 radiance = material->emissiveFactor * material->emissiveStrength;
    if (!(std::max({radiance.x, radiance.y, radiance.z}) > 0.0f)) return SceneLighting::None;
    return material->emissiveTexture.valid() && material->emissiveStrength <= 1.0f ? SceneLighting::EmissiveTexturesOnly
                                                                                      : SceneLighting::Lit;
}

SceneLighting lighting(const Scene& scene, const Node& node) {
    if (const auto* light = node.get<Light>())
        return light->intensity > 0.0f && std::max({light->color.x, light->color.y, light->color.z}) > 0.0f ? SceneLighting::Lit
                                                                                                              : SceneLighting::None;
    if (const auto* shape = node.get<Shape>()) return emission(scene, shape->material);
    SceneLighting most = SceneLighting::None;
    if (const auto* instance = node.get<MeshInstance>())
        if (const Mesh* mesh = scene.meshes.find(instance->mesh))
            for (const Primitive& p : mesh->primitives) most = std::max(most, emission(scene, p.material));
    return most;
}

} // namespace

bool environmentEmits(const Environment& environment) {
    if (environment.intensity <= 0.0f) return false;
    if (!environment.file.empty()) return true;
    return std::max({environment.color.x, environment.color.y, environment.color.z}) > 0.0f;
}

SceneLighting sceneLighting(const Scene& scene) {
    if (environmentEmits(scene.settings.environment)) return SceneLighting::Lit;
    SceneLighting most = SceneLighting::None;
    for (const NodeId id : scene.depthFirst()) {
        const Node& node = *scene.node(id);
        if (visibleInWorld(scene, node)) most = std::max(most, lighting(scene, node));
        if (most == SceneLighting::Lit) break;
    }
    return most;
}

} // namespace glint
