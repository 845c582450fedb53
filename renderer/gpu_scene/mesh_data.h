#pragma once
// The CPU side of GpuMeshes: the flattened two-level BVH, vertex attributes and emissive triangles
// of a scene's visible meshes. Mesh BVHs come from a MeshBvhCache kept across uploads, so an edit
// rebuilds only what it changed: a transform change rebuilds the top level alone. CPU only: the
// incremental path is tested byte for byte against a full build without a GL context.
#include "renderer/bvh/flat_scene.h"
#include "renderer/gpu_scene/emissive_triangles.h"
#include "renderer/gpu_scene/texture_set.h"
#include "scene/core/scene.h"

#include <cstddef>
#include <functional>
#include <map>
#include <vector>

namespace glint::renderer {

// Mesh BVHs by mesh id, keyed by their content (the triangles and material indices they were built
// from), so a stale entry is never used whatever a change set claims.
class MeshBvhCache {
public:
    // The BVH of `triangles` for `mesh`: the cached one when its input is identical, else built.
    const bvh::MeshBvh& get(MeshId mesh, bvh::MeshTriangles triangles);
    // Drops entries of meshes not in `used` (deleted or hidden meshes do not pin memory).
    void keepOnly(const std::vector<MeshId>& used);
    std::size_t builds() const { return builds_; } // BVH builds so far: what tests count
    std::size_t size() const { return entries_.size(); }

private:
    struct Entry {
        bvh::MeshTriangles input;
        bvh::MeshBvh bvh;
    };
    std::map<MeshId, Entry> entries_;
    std::size_t builds_ = 0;
};

struct MeshData {
    std::vector<bvh::MeshBvh> bvhs;       // one per instanced mesh with triangles, mesh-id order
    std::vector<MeshId> ids;              // mesh BVH index -> mesh id
    std::vector<bvh::Instance> instances; // depth-first order per mesh
    bvh::FlatScene flat;
    std::vector<glm::vec4> vertexTexels;  // layout of shaders/pathtrace/meshes.glsl
    EmissiveTriangles lights;
};

// Everything from scratch except the mesh BVHs `cache` already holds. `beforeMesh(i, n)` runs
// before each of the n mesh BVHs is fetched or built (progress; it may throw to stop the build).
// `textures`: the scene's texture set, whose mean colours weigh emissive-textured triangles as lights
// (none: such triangles are not light-sampled).
MeshData buildMeshData(const Scene& scene, const std::map<MaterialId, int>& materialIndex, bool texturing,
                       MeshBvhCache& cache, const std::function<void(std::size_t, std::size_t)>& beforeMesh = {},
                       const TextureSet* textures = nullptr);

// buildMeshData plus the BVH's validation (bvh/validate.h), CPU only: what GpuMeshes(MeshData)
// uploads. Throws std::runtime_error when the BVH is invalid.
MeshData validatedMeshData(const Scene& scene, const std::map<MaterialId, int>& materialIndex, bool texturing, MeshBvhCache& cache,
                           const std::function<void(std::size_t, std::size_t)>& beforeMesh = {},
                           const TextureSet* textures = nullptr);

// After transforms alone changed (same visible instances, same meshes and materials): new instance
// matrices, top level and emissive triangles; mesh BVHs, triangles and vertex attributes are kept.
// Gives the same bytes as buildMeshData of `scene`.
void updateMeshTransforms(MeshData& data, const Scene& scene, const std::map<MaterialId, int>& materialIndex,
                          const TextureSet* textures = nullptr);

// After material content alone changed: the emissive triangles (their emission is the materials')
// and the triangles' culling marks. Returns whether a mark changed (the positions need uploading).
bool updateMeshEmission(MeshData& data, const Scene& scene, const std::map<MaterialId, int>& materialIndex,
                        const TextureSet* textures = nullptr);

// Whether camera rays pass the back faces of a mesh with this material: single-sided and emitting
// nothing (an emitter's back face shows as unlit instead). The HAS_SINGLE_SIDED variant and the
// triangles' culling marks both follow it.
bool culledFromBehind(const Material& m);

// Marks each triangle slot whose material is single-sided and emits nothing, whose back face camera
// rays pass (shaders/pathtrace/triangle_filter.glsl): w = 1 in the slot's first position texel, so
// the filter reads the mark with the position the triangle test fetched, not the material. Returns
// whether a mark changed.
bool markCulledTriangles(bvh::FlatScene& flat, const Scene& scene, const std::map<MaterialId, int>& materialIndex);

} // namespace glint::renderer
