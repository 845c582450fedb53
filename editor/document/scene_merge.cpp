#include "scene_merge.h"

#include "scene/history/asset_commands.h"
#include "scene/history/node_commands.h"

#include <algorithm>
#include <map>

namespace glint::editor {
namespace {

// The next id a table would give out: one past its largest id.
template <class Table>
std::uint32_t nextId(const Table& table) {
    std::uint32_t next = 1;
    for (const auto& [id, value] : table) next = std::max(next, id.value + 1);
    return next;
}

template <class IdT>
using Remap = std::map<IdT, IdT>;

template <class IdT>
IdT mapped(const Remap<IdT>& remap, IdT id) {
    auto it = remap.find(id);
    return it == remap.end() ? IdT{} : it->second;
}

void remapMaterial(Material& m, const Remap<TextureId>& textures) {
    for (TextureRef* ref : {&m.baseColorTexture, &m.metallicRoughnessTexture, &m.normalTexture, &m.occlusionTexture,
                            &m.emissiveTexture, &m.specularTexture, &m.specularColorTexture, &m.transmissionTexture,
                            &m.thicknessTexture})
        if (ref->valid()) ref->texture = mapped(textures, ref->texture);
}

// Moves every asset of one table into a command under a fresh id and records the mapping. Moved,
// not copied: the merge runs on the GUI thread, and an imported mesh can be hundreds of megabytes.
template <class T, class IdT, class Fix>
Remap<IdT> addAssets(AssetTable<IdT, T>& source, std::uint32_t next, std::vector<CommandPtr>& out, Fix fix) {
    Remap<IdT> remap;
    for (auto& [id, value] : source) {
        IdT fresh{next++};
        remap[id] = fresh;
        T moved = std::move(value);
        fix(moved);
        out.push_back(std::make_unique<AddAsset<T>>(std::move(moved), fresh));
    }
    return remap;
}

struct AssetRemaps {
    Remap<MeshId> meshes;
    Remap<MaterialId> materials;
};

AssetRemaps addAllAssets(const Scene& target, Scene& imported, std::vector<CommandPtr>& out) {
    auto keep = [](auto&) {};
    auto images = addAssets(imported.images, nextId(target.images), out, keep);
    auto samplers = addAssets(imported.samplers, nextId(target.samplers), out, keep);
    auto textures = addAssets(imported.textures, nextId(target.textures), out, [&](Texture& t) {
        t.image = mapped(images, t.image);
        t.sampler = mapped(samplers, t.sampler);
    });
    AssetRemaps remaps;
    remaps.materials = addAssets(imported.materials, nextId(target.materials), out,
                                 [&](Material& m) { remapMaterial(m, textures); });
    remaps.meshes = addAssets(imported.meshes, nextId(target.meshes), out, [&](Mesh& mesh) {
        for (Primitive& p : mesh.primitives) p.material = mapped(remaps.materials, p.material);
    });
    return remaps;
}

void remapComponent(Component& component, const AssetRemaps& remaps) {
    if (auto* instance = std::get_if<MeshInstance>(&component)) instance->mesh = mapped(remaps.meshes, instance->mesh);
    if (auto* shape = std::get_if<Shape>(&component)) shape->material = mapped(remaps.materials, shape->material);
}

} // namespace

std::vector<CommandPtr> mergeCommands(const Scene& target, Scene&& imported) {
    std::vector<CommandPtr> out;
    const AssetRemaps remaps = addAllAssets(target, imported, out);
    // Every id first: a portal quad may name a node that comes after it.
    std::map<NodeId, NodeId> nodes;
    std::uint32_t next = target.peekNextNodeId().value;
    for (NodeId id : imported.depthFirst()) nodes[id] = NodeId{next++};
    for (NodeId id : imported.depthFirst()) { // parents come before their children
        const Node& source = imported.at(id);
        Node copy = source;
        copy.id = nodes.at(id);
        copy.parent = {};
        copy.children.clear();
        remapComponent(copy.component, remaps);
        if (auto* shape = std::get_if<Shape>(&copy.component)) shape->portal = mapped(nodes, shape->portal);
        NodeId parent = source.parent ? nodes.at(source.parent) : NodeId{};
        out.push_back(std::make_unique<AddNode>(std::move(copy), parent));
    }
    return out;
}

} // namespace glint::editor
