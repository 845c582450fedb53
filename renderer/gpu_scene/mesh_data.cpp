#include "renderer/gpu_scene/mesh_data.h"

#include "renderer/bvh/bvh_layout.h"
#include "renderer/bvh/mesh_bvh.h"
#include "renderer/bvh/validate.h"
#include "renderer/gpu_scene/texture_refs.h"
#include "renderer/gpu_scene/visibility.h"

#include <algorithm>
#include <stdexcept>
#include <thread>

namespace glint::renderer {
namespace {

bool sameInput(const bvh::MeshTriangles& a, const bvh::MeshTriangles& b) {
    return a.positions == b.positions && a.triangles == b.triangles && a.materials == b.materials;
}

// Visible mesh instances by mesh id, each mesh's users in depth-first order.
std::map<MeshId, std::vector<NodeId>> meshUsers(const Scene& scene) {
    std::map<MeshId, std::vector<NodeId>> users;
    for (const NodeId id : scene.depthFirst()) {
        const Node& node = scene.at(id);
        if (const auto* instance = node.get<MeshInstance>(); instance && visibleInWorld(scene, node) && scene.meshes.contains(instance->mesh))
            users[instance->mesh].push_back(id);
    }
    return users;
}

// The instances of the meshes in `ids` (BVH index order), with the scene's current transforms.
std::vector<bvh::Instance> meshInstances(const Scene& scene, const std::vector<MeshId>& ids) {
    const auto users = meshUsers(scene);
    std::vector<bvh::Instance> instances;
    for (std::size_t i = 0; i < ids.size(); ++i) {
        const auto it = users.find(ids[i]);
        if (it == users.end()) continue;
        for (const NodeId node : it->second)
            instances.push_back({scene.worldFromNode(node), bvh::kInstanceMesh, static_cast<std::uint32_t>(i), node.value, {}});
    }
    return instances;
}

// Vertex data in the vertex order of FlatScene::meshes: the normal (zero where a primitive has
// none); with `texturing` also (uv0, uv1), the tangent (zero: none) and COLOR_0 (white: none), the
// layout of shaders/pathtrace/meshes.glsl.
std::vector<glm::vec4> vertexTexels(const Scene& scene, const std::vector<MeshId>& ids, bool texturing) {
    std::vector<glm::vec4> texels;
    for (const MeshId id : ids)
        for (const Primitive& p : scene.meshes.at(id).primitives)
            for (std::size_t v = 0; v < p.positions.size(); ++v) {
                texels.push_back(glm::vec4(v < p.normals.size() ? p.normals[v] : glm::vec3(0.0f), 0.0f));
                if (!texturing) continue;
                texels.push_back({v < p.uv0.size() ? p.uv0[v] : glm::vec2(0.0f), v < p.uv1.size() ? p.uv1[v] : glm::vec2(0.0f)});
                texels.push_back(v < p.tangents.size() ? p.tangents[v] : glm::vec4(0.0f));
                texels.push_back(v < p.colors.size() ? p.colors[v] : glm::vec4(1.0f));
            }
    return texels;
}

// Slot -> triangle inverted, for the meshes with emissive-textured triangles only.
std::vector<std::uint32_t> slotOfTriangle(const bvh::MeshBvh& mesh) {
    std::vector<std::uint32_t> slots(mesh.bvh.itemOrder.size());
    for (std::size_t slot = 0; slot < mesh.bvh.itemOrder.size(); ++slot) slots[mesh.bvh.itemOrder[slot]] = static_cast<std::uint32_t>(slot);
    return slots;
}

EmissiveTriangles emissiveTriangles(const Scene& scene, const MeshData& data, const std::map<MaterialId, int>& materialIndex,
                                    const TextureSet* textures) {
    std::vector<glm::vec3> emissionOf(materialIndex.size() + 1, glm::vec3(0.0f));
    std::vector<bool> twoSidedOf(materialIndex.size() + 1, true);
    std::vector<bool> texturedOf(materialIndex.size() + 1, false);
    for (const auto& [id, index] : materialIndex) {
        const Material& material = scene.materials.at(id);
        emissionOf[static_cast<std::size_t>(index)] = sampledEmission(scene, material, textures);
        twoSidedOf[static_cast<std::size_t>(index)] = material.doubleSided;
        texturedOf[static_cast<std::size_t>(index)] = hasEmissiveTexture(scene, material);
    }
    EmissiveTriangles lights;
    std::map<std::uint32_t, std::vector<std::uint32_t>> slotsOf; // mesh BVH index -> slotOfTriangle
    for (const bvh::Instance& instance : data.instances) {
        const bvh::MeshTriangles& mesh = data.bvhs[instance.target].triangles;
        // A mirroring transform turns the winding around; the front stays where the transformed
        // normal points (glTF), so such triangles are stored with two vertices swapped.
        const bool mirrored = glm::determinant(glm::mat3(instance.worldFromLocal)) < 0.0f;
        for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
            const glm::vec3 emission = emissionOf.at(mesh.materials[t]);
            if (emission == glm::vec3(0.0f)) continue;
            const auto world = [&](std::uint32_t v) { return glm::vec3(instance.worldFromLocal * glm::vec4(mesh.positions[v], 1.0f)); };
            const glm::uvec3 v = mesh.triangles[t];
            std::optional<EmitterTexturing> texturing;
            if (texturedOf.at(mesh.materials[t])) {
                auto slots = slotsOf.find(instance.target);
                if (slots == slotsOf.end()) slots = slotsOf.emplace(instance.target, slotOfTriangle(data.bvhs[instance.target])).first;
                texturing = EmitterTexturing{data.flat.meshes.at(instance.target).firstSlot + slots->second.at(t), mirrored};
            }
            lights.add(world(v.x), world(mirrored ? v.z : v.y), world(mirrored ? v.y : v.z), emission, twoSidedOf.at(mesh.materials[t]),
                       texturing);
        }
    }
    lights.finish();
    return lights;
}

} // namespace

const bvh::MeshBvh& MeshBvhCache::get(MeshId mesh, bvh::MeshTriangles triangles) {
    const auto it = entries_.find(mesh);
    if (it != entries_.end() && sameInput(it->second.input, triangles)) return it->second.bvh;
    ++builds_;
    // Every core: the tree does not depend on the thread count (bvh_build.h), and a large mesh's
    // build is most of a preparation.
    bvh::BuildOptions options;
    options.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    bvh::MeshBvh built = bvh::buildMeshBvh(triangles, options);
    Entry& entry = entries_[mesh];
    entry = Entry{std::move(triangles), std::move(built)};
    return entry.bvh;
}

void MeshBvhCache::keepOnly(const std::vector<MeshId>& used) {
    std::erase_if(entries_, [&](const auto& entry) { return std::find(used.begin(), used.end(), entry.first) == used.end(); });
}

MeshData buildMeshData(const Scene& scene, const std::map<MaterialId, int>& materialIndex, bool texturing, MeshBvhCache& cache,
                       const std::function<void(std::size_t, std::size_t)>& beforeMesh, const TextureSet* textures) {
    const auto indexOf = [&](MaterialId id) {
        const auto it = materialIndex.find(id);
        return static_cast<std::uint32_t>(it == materialIndex.end() ? 0 : it->second);
    };
    MeshData data;
    const auto users = meshUsers(scene);
    std::size_t done = 0;
    for (const auto& [meshId, nodes] : users) {
        if (beforeMesh) beforeMesh(done++, users.size());
        auto triangles = bvh::trianglesFromMesh(scene.meshes.at(meshId), indexOf);
        if (triangles.triangleCount() == 0) continue;
        data.bvhs.push_back(cache.get(meshId, std::move(triangles)));
        data.ids.push_back(meshId);
    }
    cache.keepOnly(data.ids);
    data.instances = meshInstances(scene, data.ids);
    if (data.instances.empty()) return data;
    data.flat = bvh::flattenScene(data.bvhs, bvh::buildTopLevel(data.instances, data.bvhs));
    markCulledTriangles(data.flat, scene, materialIndex);
    data.vertexTexels = vertexTexels(scene, data.ids, texturing);
    data.lights = emissiveTriangles(scene, data, materialIndex, textures);
    return data;
}

MeshData validatedMeshData(const Scene& scene, const std::map<MaterialId, int>& materialIndex, bool texturing, MeshBvhCache& cache,
                           const std::function<void(std::size_t, std::size_t)>& beforeMesh, const TextureSet* textures) {
    MeshData data = buildMeshData(scene, materialIndex, texturing, cache, beforeMesh, textures);
    if (data.instances.empty()) return data;
    if (const auto problem = bvh::validateFlatScene(data.flat)) throw std::runtime_error("invalid BVH: " + *problem);
    return data;
}

void updateMeshTransforms(MeshData& data, const Scene& scene, const std::map<MaterialId, int>& materialIndex,
                          const TextureSet* textures) {
    data.instances = meshInstances(scene, data.ids);
    if (data.instances.empty()) return;
    const bvh::TopLevel topLevel = bvh::buildTopLevel(data.instances, data.bvhs);
    bvh::replaceTopLevel(data.flat, bvh::flattenTopLevel(topLevel, data.flat.meshNodeCount));
    data.lights = emissiveTriangles(scene, data, materialIndex, textures);
}

bool updateMeshEmission(MeshData& data, const Scene& scene, const std::map<MaterialId, int>& materialIndex,
                        const TextureSet* textures) {
    if (data.instances.empty()) return false;
    data.lights = emissiveTriangles(scene, data, materialIndex, textures);
    return markCulledTriangles(data.flat, scene, materialIndex);
}

bool culledFromBehind(const Material& m) {
    return !m.doubleSided && m.emissiveFactor * m.emissiveStrength == glm::vec3(0.0f);
}

bool markCulledTriangles(bvh::FlatScene& flat, const Scene& scene, const std::map<MaterialId, int>& materialIndex) {
    std::vector<float> markOf; // by the renderer's material index; indices without a material: 0
    for (const auto& [id, index] : materialIndex) {
        if (!scene.materials.contains(id) || index < 0) continue;
        if (markOf.size() <= static_cast<std::size_t>(index)) markOf.resize(static_cast<std::size_t>(index) + 1, 0.0f);
        markOf[static_cast<std::size_t>(index)] = culledFromBehind(scene.materials.at(id)) ? 1.0f : 0.0f;
    }
    bool changed = false;
    for (std::size_t slot = 0; slot < flat.triangleVertices.size(); ++slot) {
        const std::uint32_t material = flat.triangleVertices[slot].w;
        const float mark = material < markOf.size() ? markOf[material] : 0.0f;
        float& w = flat.trianglePositions[bvh::kTrianglePositionTexels * slot].w;
        changed = changed || w != mark;
        w = mark;
    }
    return changed;
}

} // namespace glint::renderer
