#pragma once
// The scene's triangle meshes on the GPU: the two-level BVH of renderer/bvh (layout in
// bvh_layout.h), per-vertex shading normals, and the emissive triangles for light sampling.
#include "renderer/gl/shader_program.h"
#include "renderer/gl/texture_buffer.h"
#include "renderer/gpu_scene/mesh_data.h"
#include "scene/core/scene.h"

#include <map>
#include <memory>
#include <optional>

namespace glint::renderer {

class GpuMeshes {
public:
    // `materialIndex`: the renderer's material table. `texturing`: upload UVs, tangents and COLOR_0
    // beside the normals (the HAS_TEXTURES layout). Throws std::runtime_error when the BVH is invalid
    // or exceeds GL_MAX_TEXTURE_BUFFER_SIZE.
    // `cache`: mesh BVHs kept across uploads (only meshes whose content changed are rebuilt).
    GpuMeshes(const Scene& scene, const std::map<MaterialId, int>& materialIndex, bool texturing, MeshBvhCache& cache);
    // The upload alone, of data validatedMeshData made (on any thread).
    explicit GpuMeshes(MeshData data);
    ~GpuMeshes();
    // After a transform-only change: rebuilds the top level and the emissive triangles and uploads
    // the node, instance and emissive buffers; mesh BVHs and vertex buffers stay as they are.
    void updateTransforms(const Scene& scene, const std::map<MaterialId, int>& materialIndex, const TextureSet* textures);
    // After a material-only change: re-uploads the emissive triangles, and the triangle positions
    // where a culling mark changed (mesh_data.h, markCulledTriangles).
    void updateEmission(const Scene& scene, const std::map<MaterialId, int>& materialIndex, const TextureSet* textures);
    const MeshData& data() const { return data_; }

    bool empty() const { return triangleCount_ == 0; }
    std::size_t triangleCount() const { return triangleCount_; }
    // Texture units firstUnit .. firstUnit + 7.
    void bind(const gl::ShaderProgram& program, GLuint firstUnit) const;

private:
    void setCounts();

    struct Buffers;
    MeshData data_;
    std::unique_ptr<Buffers> buffers_;
    std::size_t triangleCount_ = 0;
    int topLevel_ = -1;
    int emissiveCount_ = 0;
    float emissivePower_ = 0.0f;
};

} // namespace glint::renderer
