#pragma once
// A mesh as one flat triangle list across its primitives: what its BVH is built over.
#include "scene/core/ids.h"
#include "scene/core/mesh.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <functional>
#include <vector>

namespace glint::bvh {

struct MeshTriangles {
    std::vector<glm::vec3> positions;       // every primitive's vertices, primitives in order
    std::vector<glm::uvec3> triangles;      // indices into positions
    std::vector<std::uint32_t> materials;   // one per triangle
    std::vector<std::uint32_t> primitiveOf; // one per triangle: index of its glTF primitive
    std::size_t triangleCount() const { return triangles.size(); }
};

// `materialIndex` maps a primitive's material (none: glTF's default) to the renderer's index.
// Triangles whose indices fall outside their primitive are dropped (the loader checks them first).
MeshTriangles trianglesFromMesh(const Mesh& mesh, const std::function<std::uint32_t(MaterialId)>& materialIndex);

} // namespace glint::bvh
