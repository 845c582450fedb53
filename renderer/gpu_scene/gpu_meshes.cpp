#include "renderer/gpu_scene/gpu_meshes.h"

#include "renderer/bvh/bvh_layout.h"
#include "renderer/bvh/flat_scene.h"
#include "renderer/bvh/size_check.h"
#include "renderer/bvh/validate.h"
#include "renderer/gpu_scene/visibility.h"

#include <stdexcept>
#include <vector>

namespace glint::renderer {

struct GpuMeshes::Buffers {
    gl::TextureBuffer nodeBounds, nodeLinks, trianglePositions, triangleVertices, instances;
    gl::TextureBuffer vertexNormals, emissiveTriangles, emissiveCdf;
};

namespace {

struct MeshSet {
    std::vector<bvh::MeshBvh> bvhs;
    std::vector<MeshId> ids;            // mesh BVH index -> mesh id
    std::vector<bvh::Instance> instances;
};

// One BVH per mesh that a visible node instances (in mesh-id order), and the instances.
MeshSet buildMeshSet(const Scene& scene, const std::map<MaterialId, int>& materialIndex) {
    const auto indexOf = [&](MaterialId id) {
        const auto it = materialIndex.find(id);
        return static_cast<std::uint32_t>(it == materialIndex.end() ? 0 : it->second);
    };
    std::map<MeshId, std::vector<NodeId>> users;
    for (const NodeId id : scene.depthFirst()) {
        const Node& node = scene.at(id);
        if (const auto* instance = node.get<MeshInstance>(); instance && visibleInWorld(scene, node) && scene.meshes.contains(instance->mesh))
            users[instance->mesh].push_back(id);
    }
    MeshSet set;
    for (const auto& [meshId, nodes] : users) {
        auto triangles = bvh::trianglesFromMesh(scene.meshes.at(meshId), indexOf);
        if (triangles.triangleCount() == 0) continue;
        const auto meshIndex = static_cast<std::uint32_t>(set.bvhs.size());
        set.bvhs.push_back(bvh::buildMeshBvh(std::move(triangles), bvh::BuildOptions{}));
        set.ids.push_back(meshId);
        for (const NodeId node : nodes)
            set.instances.push_back({scene.worldFromNode(node), bvh::kInstanceMesh, meshIndex, node.value, {}});
    }
    return set;
}

// Vertex data in the vertex order of FlatScene::meshes: the normal (zero where a primitive has
// none); with `texturing` also (uv0, uv1), the tangent (zero: none) and COLOR_0 (white: none), the
// layout of shaders/pathtrace/meshes.glsl.
std::vector<glm::vec4> vertexTexels(const Scene& scene, const MeshSet& set, bool texturing) {
    std::vector<glm::vec4> texels;
    for (const MeshId id : set.ids)
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

// Emission that light sampling assumes: the factors. Emissive-textured materials are left to BSDF
// sampling (shaders/pathtrace/material.glsl), since a factor would misstate their texels.
glm::vec3 sampledEmission(const Scene& scene, const Material& m) {
    if (m.emissiveTexture.valid() && scene.textures.contains(m.emissiveTexture.texture)) return glm::vec3(0.0f);
    return m.emissiveFactor * m.emissiveStrength;
}

EmissiveTriangles emissiveTriangles(const Scene& scene, const MeshSet& set, const std::map<MaterialId, int>& materialIndex) {
    std::vector<glm::vec3> emissionOf(materialIndex.size() + 1, glm::vec3(0.0f));
    for (const auto& [id, index] : materialIndex) {
        emissionOf[static_cast<std::size_t>(index)] = sampledEmission(scene, scene.materials.at(id));
    }
    EmissiveTriangles lights;
    for (const bvh::Instance& instance : set.instances) {
        const bvh::MeshTriangles& mesh = set.bvhs[instance.target].triangles;
        for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
            const glm::vec3 emission = emissionOf.at(mesh.materials[t]);
            if (emission == glm::vec3(0.0f)) continue;
            const auto world = [&](std::uint32_t v) { return glm::vec3(instance.worldFromLocal * glm::vec4(mesh.positions[v], 1.0f)); };
            lights.add(world(mesh.triangles[t].x), world(mesh.triangles[t].y), world(mesh.triangles[t].z), emission);
        }
    }
    lights.finish();
    return lights;
}

template <class T>
gl::TextureBuffer upload(const char* what, GLenum format, const std::vector<T>& texels) {
    return gl::TextureBuffer(what, format, texels.data(), texels.size(), sizeof(T));
}

} // namespace

GpuMeshes::GpuMeshes(const Scene& scene, const std::map<MaterialId, int>& materialIndex, bool texturing) {
    MeshSet set = buildMeshSet(scene, materialIndex);
    if (set.instances.empty()) return;
    const bvh::TopLevel topLevel = bvh::buildTopLevel(set.instances, set.bvhs);
    const bvh::FlatScene flat = bvh::flattenScene(set.bvhs, topLevel);
    if (const auto problem = bvh::validateFlatScene(flat)) throw std::runtime_error("invalid BVH: " + *problem);
    if (const auto tooBig = bvh::checkTextureBufferSizes(flat, static_cast<std::int64_t>(gl::maxTextureBufferTexels())))
        throw std::runtime_error(*tooBig);
    const EmissiveTriangles lights = emissiveTriangles(scene, set, materialIndex);
    buffers_ = std::make_unique<Buffers>(Buffers{
        upload("uBvhNodeBounds", GL_RGBA32F, flat.nodeBounds), upload("uBvhNodeLinks", GL_RGBA32UI, flat.nodeLinks),
        upload("uBvhTrianglePositions", GL_RGBA32F, flat.trianglePositions),
        upload("uBvhTriangleVertices", GL_RGBA32UI, flat.triangleVertices), upload("uBvhInstances", GL_RGBA32UI, flat.instances),
        upload("the vertex attributes", GL_RGBA32F, vertexTexels(scene, set, texturing)),
        upload("the emissive triangles", GL_RGBA32F, lights.texels), upload("the emissive CDF", GL_R32F, lights.cdf)});
    triangleCount_ = flat.trianglePositions.size() / bvh::kTrianglePositionTexels;
    topLevelRoot_ = flat.topLevelRoot;
    emissiveCount_ = lights.count();
    emissivePower_ = lights.totalPower;
}

GpuMeshes::~GpuMeshes() = default;

void GpuMeshes::bind(const gl::ShaderProgram& program, GLuint firstUnit) const {
    if (!buffers_) return;
    const Buffers& b = *buffers_;
    b.nodeBounds.bind(firstUnit + 0, program.uniform(bvh::kNodeBoundsUniform));
    b.nodeLinks.bind(firstUnit + 1, program.uniform(bvh::kNodeLinksUniform));
    b.trianglePositions.bind(firstUnit + 2, program.uniform(bvh::kTrianglePositionsUniform));
    b.triangleVertices.bind(firstUnit + 3, program.uniform(bvh::kTriangleVerticesUniform));
    b.instances.bind(firstUnit + 4, program.uniform(bvh::kInstancesUniform));
    b.vertexNormals.bind(firstUnit + 5, program.uniform("uVertexNormals"));
    b.emissiveTriangles.bind(firstUnit + 6, program.uniform("uEmissiveTriangles"));
    b.emissiveCdf.bind(firstUnit + 7, program.uniform("uEmissiveCdf"));
    glUniform1i(program.uniform(bvh::kTopLevelRootUniform), topLevelRoot_);
    glUniform1i(program.uniform("uEmissiveCount"), emissiveCount_);
    glUniform1f(program.uniform("uEmissivePower"), emissivePower_);
}

} // namespace glint::renderer
