#pragma once
// Meshes, rays and a brute-force reference shared by the BVH tests and the benchmark.
#include "renderer/bvh/flat_scene.h"
#include "renderer/bvh/ray.h"

#include <glm/glm.hpp>

#include <random>
#include <vector>

namespace glint::bvh::test {

MeshTriangles loadBunny(); // GLINT_TEST_DATA_DIR/meshes/stanford-bunny.obj

// Each level splits every triangle into four at its edge midpoints (shared midpoints: the mesh
// stays closed where it was closed).
MeshTriangles subdivided(const MeshTriangles& mesh, int levels);

// The surface of the cube [0, cells]^3 scaled by `cellSize` and moved by `origin`: a closed mesh
// with shared vertices, counter-clockwise seen from outside.
MeshTriangles closedGridCube(int cells, float cellSize, const glm::vec3& origin);

// Flat scene of meshes, each placed by its transform (one instance per entry of `placements`).
struct Placement {
    std::uint32_t mesh;
    glm::mat4 worldFromLocal;
};
struct TestScene {
    std::vector<MeshBvh> meshes;
    std::vector<Placement> placements;
    TopLevel topLevel;
    FlatScene flat;
};
TestScene makeScene(std::vector<MeshTriangles> meshes, std::vector<Placement> placements, int threads = 1);

// Rewrites node's link (first, count) where both the link texel and the node's bounds carry it.
void setLink(FlatScene& scene, std::uint32_t node, std::uint32_t first, std::uint32_t count);

// A ray from a random point of `bounds` grown by half its size towards a random point inside it.
Ray randomRayThrough(std::mt19937& rng, const Aabb& bounds);

// Every triangle of every instance tested in index order; the local ray is computed from
// inverse(worldFromLocal) exactly as the instance texels store it. Ties keep the first triangle.
RayHit bruteForceClosest(const TestScene& scene, const Ray& worldRay, float tMax);

} // namespace glint::bvh::test
