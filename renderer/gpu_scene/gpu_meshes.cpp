#include "renderer/gpu_scene/gpu_meshes.h"

#include "renderer/bvh/bvh_layout.h"
#include "renderer/bvh/size_check.h"
#include "renderer/bvh/validate.h"

#include <stdexcept>
#include <vector>

namespace glint::renderer {

struct GpuMeshes::Buffers {
    gl::TextureBuffer nodes, levels, trianglePositions, triangleVertices, instances;
    gl::TextureBuffer vertexNormals, emissiveTriangles, emissiveCdf;
};

namespace {

template <class T>
gl::TextureBuffer upload(const char* what, GLenum format, const std::vector<T>& texels) {
    return gl::TextureBuffer(what, format, texels.data(), texels.size(), sizeof(T));
}

void checkTopLevel(const bvh::FlatScene& flat) {
    if (const auto problem = bvh::validateTopLevel(flat)) throw std::runtime_error("invalid BVH: " + *problem);
}

// Rewrites the texels from `first` on where the buffer keeps its length, else uploads it anew.
template <class T>
void replaceTail(gl::TextureBuffer& buffer, const char* what, GLenum format, const std::vector<T>& texels, std::size_t first) {
    if (buffer.texels() == texels.size() && first <= texels.size())
        buffer.update(first, texels.data() + first, texels.size() - first);
    else
        buffer = upload(what, format, texels);
}

void checkSizes(const bvh::FlatScene& flat) {
    if (const auto tooBig = bvh::checkTextureBufferSizes(flat, static_cast<std::int64_t>(gl::maxTextureBufferTexels())))
        throw std::runtime_error(*tooBig);
}

} // namespace

GpuMeshes::GpuMeshes(const Scene& scene, const std::map<MaterialId, int>& materialIndex, bool texturing, MeshBvhCache& cache)
    : GpuMeshes(validatedMeshData(scene, materialIndex, texturing, cache)) {}

GpuMeshes::GpuMeshes(MeshData data) : data_(std::move(data)) {
    if (data_.instances.empty()) return;
    const bvh::FlatScene& flat = data_.flat;
    checkSizes(flat); // validated on the CPU already (validatedMeshData), off the GL thread
    buffers_ = std::make_unique<Buffers>(Buffers{
        upload(bvh::kNodesUniform, GL_RGBA32UI, flat.nodes), upload(bvh::kLevelsUniform, GL_RGBA32UI, flat.levels),
        upload("uBvhTrianglePositions", GL_RGBA32F, flat.trianglePositions),
        upload("uBvhTriangleVertices", GL_RGBA32UI, flat.triangleVertices), upload("uBvhInstances", GL_RGBA32UI, flat.instances),
        upload("the vertex attributes", GL_RGBA32F, data_.vertexTexels),
        upload("the emissive triangles", GL_RGBA32F, data_.lights.texels), upload("the emissive CDF", GL_R32F, data_.lights.cdf)});
    setCounts();
}

GpuMeshes::~GpuMeshes() = default;

void GpuMeshes::updateTransforms(const Scene& scene, const std::map<MaterialId, int>& materialIndex, const TextureSet* textures) {
    if (!buffers_) return;
    const bool hadEmitters = !data_.lights.texels.empty();
    updateMeshTransforms(data_, scene, materialIndex, textures);
    // The mesh trees did not change (validated when they were prepared): only the top level is
    // checked and rewritten, after the mesh nodes and levels in their buffers (glBufferSubData).
    // Checking and re-sending every mesh node cost 100 ms per gizmo-drag frame on 1.1 M unique triangles.
    checkTopLevel(data_.flat);
    checkSizes(data_.flat);
    Buffers& b = *buffers_;
    const std::size_t meshNodes = data_.flat.meshNodeCount;
    replaceTail(b.nodes, bvh::kNodesUniform, GL_RGBA32UI, data_.flat.nodes, bvh::kNodeTexels * meshNodes);
    replaceTail(b.levels, bvh::kLevelsUniform, GL_RGBA32UI, data_.flat.levels, bvh::kLevelTexels * data_.flat.meshes.size());
    replaceTail(b.instances, "uBvhInstances", GL_RGBA32UI, data_.flat.instances, 0);
    if (hadEmitters || !data_.lights.texels.empty()) {
        b.emissiveTriangles = upload("the emissive triangles", GL_RGBA32F, data_.lights.texels);
        b.emissiveCdf = upload("the emissive CDF", GL_R32F, data_.lights.cdf);
    }
    setCounts();
}

void GpuMeshes::updateEmission(const Scene& scene, const std::map<MaterialId, int>& materialIndex, const TextureSet* textures) {
    if (!buffers_) return;
    if (updateMeshEmission(data_, scene, materialIndex, textures))
        buffers_->trianglePositions.update(0, data_.flat.trianglePositions.data(), data_.flat.trianglePositions.size());
    buffers_->emissiveTriangles = upload("the emissive triangles", GL_RGBA32F, data_.lights.texels);
    buffers_->emissiveCdf = upload("the emissive CDF", GL_R32F, data_.lights.cdf);
    setCounts();
}

void GpuMeshes::setCounts() {
    triangleCount_ = data_.flat.trianglePositions.size() / bvh::kTrianglePositionTexels;
    topLevel_ = data_.flat.topLevel;
    emissiveCount_ = data_.lights.count();
    emissivePower_ = data_.lights.totalPower;
}

void GpuMeshes::bind(const gl::ShaderProgram& program, GLuint firstUnit) const {
    if (!buffers_) return;
    const Buffers& b = *buffers_;
    b.nodes.bind(firstUnit + 0, program.uniform(bvh::kNodesUniform));
    b.levels.bind(firstUnit + 1, program.uniform(bvh::kLevelsUniform));
    b.trianglePositions.bind(firstUnit + 2, program.uniform(bvh::kTrianglePositionsUniform));
    b.triangleVertices.bind(firstUnit + 3, program.uniform(bvh::kTriangleVerticesUniform));
    b.instances.bind(firstUnit + 4, program.uniform(bvh::kInstancesUniform));
    b.vertexNormals.bind(firstUnit + 5, program.uniform("uVertexNormals"));
    b.emissiveTriangles.bind(firstUnit + 6, program.uniform("uEmissiveTriangles"));
    b.emissiveCdf.bind(firstUnit + 7, program.uniform("uEmissiveCdf"));
    glUniform1i(program.uniform(bvh::kTopLevelUniform), topLevel_);
    glUniform1i(program.uniform("uEmissiveCount"), emissiveCount_);
    glUniform1f(program.uniform("uEmissivePower"), emissivePower_);
}

} // namespace glint::renderer
