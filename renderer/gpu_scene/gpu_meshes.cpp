#include "renderer/gpu_scene/gpu_meshes.h"

#include "renderer/bvh/bvh_layout.h"
#include "renderer/bvh/size_check.h"
#include "renderer/bvh/validate.h"

#include <stdexcept>
#include <vector>

namespace glint::renderer {

struct GpuMeshes::Buffers {
    gl::TextureBuffer nodeBounds, nodeLinks, trianglePositions, triangleVertices, instances;
    gl::TextureBuffer vertexNormals, emissiveTriangles, emissiveCdf;
};

namespace {

template <class T>
gl::TextureBuffer upload(const char* what, GLenum format, const std::vector<T>& texels) {
    return gl::TextureBuffer(what, format, texels.data(), texels.size(), sizeof(T));
}

void validate(const bvh::FlatScene& flat) {
    if (const auto problem = bvh::validateFlatScene(flat)) throw std::runtime_error("invalid BVH: " + *problem);
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
        upload("uBvhNodeBounds", GL_RGBA32F, flat.nodeBounds), upload("uBvhNodeLinks", GL_RGBA32UI, flat.nodeLinks),
        upload("uBvhTrianglePositions", GL_RGBA32F, flat.trianglePositions),
        upload("uBvhTriangleVertices", GL_RGBA32UI, flat.triangleVertices), upload("uBvhInstances", GL_RGBA32UI, flat.instances),
        upload("the vertex attributes", GL_RGBA32F, data_.vertexTexels),
        upload("the emissive triangles", GL_RGBA32F, data_.lights.texels), upload("the emissive CDF", GL_R32F, data_.lights.cdf)});
    setCounts();
}

GpuMeshes::~GpuMeshes() = default;

void GpuMeshes::updateTransforms(const Scene& scene, const std::map<MaterialId, int>& materialIndex) {
    if (!buffers_) return;
    updateMeshTransforms(data_, scene, materialIndex);
    validate(data_.flat);
    checkSizes(data_.flat);
    // The node buffers hold the mesh nodes too; re-sending them is a copy, not a BVH build.
    Buffers& b = *buffers_;
    b.nodeBounds = upload("uBvhNodeBounds", GL_RGBA32F, data_.flat.nodeBounds);
    b.nodeLinks = upload("uBvhNodeLinks", GL_RGBA32UI, data_.flat.nodeLinks);
    b.instances = upload("uBvhInstances", GL_RGBA32UI, data_.flat.instances);
    b.emissiveTriangles = upload("the emissive triangles", GL_RGBA32F, data_.lights.texels);
    b.emissiveCdf = upload("the emissive CDF", GL_R32F, data_.lights.cdf);
    setCounts();
}

void GpuMeshes::updateEmission(const Scene& scene, const std::map<MaterialId, int>& materialIndex) {
    if (!buffers_) return;
    updateMeshEmission(data_, scene, materialIndex);
    buffers_->emissiveTriangles = upload("the emissive triangles", GL_RGBA32F, data_.lights.texels);
    buffers_->emissiveCdf = upload("the emissive CDF", GL_R32F, data_.lights.cdf);
    setCounts();
}

void GpuMeshes::setCounts() {
    triangleCount_ = data_.flat.trianglePositions.size() / bvh::kTrianglePositionTexels;
    topLevelRoot_ = data_.flat.topLevelRoot;
    emissiveCount_ = data_.lights.count();
    emissivePower_ = data_.lights.totalPower;
}

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
