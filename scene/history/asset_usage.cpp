#include "asset_usage.h"

#include <algorithm>

namespace glint {
namespace {

template <class Pred>
bool anyNode(const Scene& scene, Pred pred) {
    return std::any_of(scene.nodes().begin(), scene.nodes().end(), [&](const auto& entry) { return pred(entry.second); });
}

template <class T, class IdT, class Pred>
bool anyAsset(const AssetTable<IdT, T>& table, Pred pred) {
    return std::any_of(table.begin(), table.end(), [&](const auto& entry) { return pred(entry.second); });
}

bool materialReads(const Material& m, TextureId texture) {
    const TextureRef* slots[] = {&m.baseColorTexture,     &m.metallicRoughnessTexture, &m.normalTexture,
                                 &m.occlusionTexture,     &m.emissiveTexture,          &m.specularTexture,
                                 &m.specularColorTexture, &m.transmissionTexture,      &m.thicknessTexture};
    return std::any_of(std::begin(slots), std::end(slots), [&](const TextureRef* ref) { return ref->texture == texture; });
}

} // namespace

bool isInUse(const Scene& scene, MeshId mesh) {
    return anyNode(scene, [&](const Node& n) {
        const auto* instance = n.get<MeshInstance>();
        return instance && instance->mesh == mesh;
    });
}

bool isInUse(const Scene& scene, MaterialId material) {
    const bool byShape = anyNode(scene, [&](const Node& n) {
        const auto* shape = n.get<Shape>();
        return shape && shape->material == material;
    });
    return byShape || anyAsset(scene.meshes, [&](const Mesh& mesh) {
               return std::any_of(mesh.primitives.begin(), mesh.primitives.end(),
                                  [&](const Primitive& p) { return p.material == material; });
           });
}

bool isInUse(const Scene& scene, TextureId texture) {
    return anyAsset(scene.materials, [&](const Material& m) { return materialReads(m, texture); });
}

bool isInUse(const Scene& scene, ImageId image) {
    return anyAsset(scene.textures, [&](const Texture& t) { return t.image == image; });
}

bool isInUse(const Scene& scene, SamplerId sampler) {
    return anyAsset(scene.textures, [&](const Texture& t) { return t.sampler == sampler; });
}

} // namespace glint
