#pragma once
// A scene snapshot compiled into GPU data: texture buffers of shapes, materials and lights, the
// meshes' BVH, and the environment. Prepared on the CPU (prepared_scene.h: any thread), uploaded on
// the GL thread; binds itself to a path-trace program.
#include "renderer/gl/shader_program.h"
#include "renderer/gl/texture_buffer.h"
#include "renderer/gpu_scene/gpu_meshes.h"
#include "renderer/gpu_scene/packed_scene.h"
#include "renderer/gpu_scene/prepared_scene.h"
#include "renderer/gpu_scene/texture_arrays.h"

#include <filesystem>
#include <optional>
#include <set>

namespace glint::renderer {

// The GGX energy tables (renderer/cpu_twin/ggx_energy_tables.h, the C++ twin's floats) as a uniform
// buffer, and pointing `program`'s block GgxEnergyTables (shaders/bsdf/ggx_energy.glsl) at it through
// uniform-buffer binding 0; a program without the block is left alone. GpuScene does both; probes too.
gl::Buffer uploadGgxEnergyTables();
void bindGgxEnergyTables(const gl::ShaderProgram& program, const gl::Buffer& tables);

class GpuScene {
public:
    // `environmentFile`: an equirectangular image, or empty for the project's uniform colour.
    // `meshCache`: mesh BVHs kept across uploads; meshes whose content is unchanged are not rebuilt.
    // Prepares (prepareScene with this context's texture limits) and uploads in one step.
    // `textureCache`: decoded and mip-mapped images kept across uploads (none: decode every image).
    GpuScene(const Scene& scene, const std::filesystem::path& environmentFile, MeshBvhCache& meshCache,
             TextureCache* textureCache = nullptr);
    // The GL stage alone: uploads what prepareScene made, possibly on another thread.
    explicit GpuScene(PreparedScene prepared);

    // After a change of transforms alone (same visible nodes, meshes, materials, lights and
    // environment): re-uploads the shape and light buffers, the top-level BVH, the instance table
    // and the emissive triangles; mesh BVHs, vertex data, materials, textures and environment stay.
    // Gives the bytes a full upload of `scene` would.
    void updateTransforms(const Scene& scene);
    // After a change of material content alone (no image content changed): when the materials
    // sample the same images and need the same shader variant, re-uploads the material buffer and
    // the emissive triangles and returns true; false: nothing was done, a full upload is needed.
    bool updateMaterials(const Scene& scene);
    const GpuMeshes& meshes() const { return meshes_; }
    const PackedScene& packed() const { return packed_; }

    const SceneFeatures& features() const { return features_; }
    // Problems that did not stop the upload (missing or undecodable textures, resampled sizes).
    const Warnings& warnings() const { return warnings_; }
    // Binds the buffers to texture units 0..12, the texture arrays to 13..15 (the 16 units GL 4.1
    // guarantees), the GGX energy tables to uniform-buffer binding 0 (the program's block
    // GgxEnergyTables), and sets the scene uniforms of `program`.
    void bind(const gl::ShaderProgram& program) const;

private:
    void noteAreaEmitters();

    SceneFeatures features_;
    PackedScene packed_;
    Environment environment_;
    Fog fog_;
    gl::TextureBuffer shapes_;
    gl::TextureBuffer materials_;
    gl::TextureBuffer lights_;
    gl::Buffer ggxEnergyTables_; // shaders/bsdf/ggx_energy.glsl's uniform block, std140
    GpuMeshes meshes_;
    gl::Texture environmentMap_;
    gl::Texture environmentCdf_; // renderer/cpu_twin/env_sampling.h layout
    glm::ivec2 environmentSize_{0};
    TextureArrays textureArrays_;
    TextureSet textureSlots_; // where each image lives (no pixels): material records point there
    std::set<std::pair<ImageId, bool>> texturesUsed_;
    Warnings warnings_;
};

} // namespace glint::renderer
