#include "bvh_test_scenes.h"

#include "obj_reader.h"
#include "renderer/bvh/bvh_layout.h"
#include "renderer/bvh/triangle_intersect.h"

#include <map>
#include <tuple>
#include <unordered_map>

namespace glint::bvh::test {

MeshTriangles loadBunny()
{
    return readObjTriangles(std::filesystem::path(GLINT_TEST_DATA_DIR) / "meshes" / "stanford-bunny.obj");
}

MeshTriangles subdivided(const MeshTriangles& mesh, int levels)
{
    MeshTriangles current = mesh;
    for (int level = 0; level < levels; ++level) {
        MeshTriangles next;
        next.positions = current.positions;
        std::unordered_map<std::uint64_t, std::uint32_t> midpoints; // looked up only, never iterated
        const auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
            const std::uint64_t key = (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
            const auto [it, inserted] = midpoints.try_emplace(key, static_cast<std::uint32_t>(next.positions.size()));
            if (inserted) next.positions.push_back(0.5f * (current.positions[a] + current.positions[b]));
            return it->second;
        };
        for (std::size_t t = 0; t < current.triangleCount(); ++t) {
            const glm::uvec3 tri = current.triangles[t];
            const std::uint32_t ab = midpoint(tri.x, tri.y), bc = midpoint(tri.y, tri.z), ca = midpoint(tri.z, tri.x);
            for (const glm::uvec3 child : {glm::uvec3(tri.x, ab, ca), glm::uvec3(ab, tri.y, bc), glm::uvec3(ca, bc, tri.z),
                                           glm::uvec3(ab, bc, ca)}) {
                next.triangles.push_back(child);
                next.materials.push_back(current.materials[t]);
                next.primitiveOf.push_back(current.primitiveOf[t]);
            }
        }
        current = std::move(next);
    }
    return current;
}

MeshTriangles closedGridCube(int cells, float cellSize, const glm::vec3& origin)
{
    MeshTriangles mesh;
    std::map<std::tuple<int, int, int>, std::uint32_t> vertexOf;
    const auto vertex = [&](glm::ivec3 grid) {
        const auto key = std::make_tuple(grid.x, grid.y, grid.z);
        const auto [it, inserted] = vertexOf.try_emplace(key, static_cast<std::uint32_t>(mesh.positions.size()));
        if (inserted) mesh.positions.push_back(origin + cellSize * glm::vec3(grid));
        return it->second;
    };
    for (int axis = 0; axis < 3; ++axis) {
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        for (int side = 0; side < 2; ++side) {
            for (int i = 0; i < cells; ++i) {
                for (int j = 0; j < cells; ++j) {
                    const auto corner = [&](int di, int dj) {
                        glm::ivec3 g{0};
                        g[axis] = side * cells;
                        g[u] = i + di;
                        g[v] = j + dj;
                        return vertex(g);
                    };
                    const std::uint32_t p00 = corner(0, 0), p10 = corner(1, 0), p11 = corner(1, 1), p01 = corner(0, 1);
                    // cross(u, v) points along +axis: keep that winding on the far side, flip it on the near one.
                    const glm::uvec3 first = side == 1 ? glm::uvec3(p00, p10, p11) : glm::uvec3(p00, p11, p10);
                    const glm::uvec3 second = side == 1 ? glm::uvec3(p00, p11, p01) : glm::uvec3(p00, p01, p11);
                    for (const glm::uvec3 tri : {first, second}) {
                        mesh.triangles.push_back(tri);
                        mesh.materials.push_back(0);
                        mesh.primitiveOf.push_back(0);
                    }
                }
            }
        }
    }
    return mesh;
}

TestScene makeScene(std::vector<MeshTriangles> meshes, std::vector<Placement> placements, int threads)
{
    TestScene scene;
    BuildOptions options;
    options.threads = threads;
    for (MeshTriangles& mesh : meshes) scene.meshes.push_back(buildMeshBvh(std::move(mesh), options));
    std::vector<Instance> instances;
    for (std::size_t i = 0; i < placements.size(); ++i)
        instances.push_back(Instance{placements[i].worldFromLocal, kInstanceMesh, placements[i].mesh, static_cast<std::uint32_t>(i + 1), {}});
    scene.placements = std::move(placements);
    scene.topLevel = buildTopLevel(std::move(instances), scene.meshes);
    scene.flat = flattenScene(scene.meshes, scene.topLevel);
    return scene;
}

void setLink(FlatScene& scene, std::uint32_t node, std::uint32_t first, std::uint32_t count)
{
    scene.nodes[node].w = packLink(glm::uvec2(first, count));
    for (std::size_t mesh = 0; mesh < scene.meshes.size(); ++mesh)
        if (scene.meshes[mesh].rootNode == node) scene.levels[kLevelTexels * mesh].w = scene.nodes[node].w;
}

Ray randomRayThrough(std::mt19937& rng, const Aabb& bounds)
{
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const glm::vec3 size = bounds.extent();
    const auto pointIn = [&](float grow) {
        const glm::vec3 r{unit(rng), unit(rng), unit(rng)};
        return bounds.lo - grow * size + (1.0f + 2.0f * grow) * size * r;
    };
    const glm::vec3 origin = pointIn(0.5f);
    return Ray{origin, pointIn(0.0f) - origin};
}

namespace {

Ray localRay(const glm::mat4& worldFromLocal, const Ray& world)
{
    const glm::mat4 m = glm::inverse(worldFromLocal);
    Ray local;
    for (int r = 0; r < 3; ++r) {
        local.origin[r] = m[0][r] * world.origin.x + m[1][r] * world.origin.y + m[2][r] * world.origin.z + m[3][r];
        local.direction[r] = m[0][r] * world.direction.x + m[1][r] * world.direction.y + m[2][r] * world.direction.z;
    }
    return local;
}

} // namespace

RayHit bruteForceClosest(const TestScene& scene, const Ray& worldRay, float tMax)
{
    RayHit best;
    for (std::size_t i = 0; i < scene.topLevel.instances.size(); ++i) {
        const Instance& instance = scene.topLevel.instances[i];
        const MeshTriangles& mesh = scene.meshes[instance.target].triangles;
        const WatertightRay ray = prepareWatertight(localRay(instance.worldFromLocal, worldRay));
        for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
            const glm::uvec3 tri = mesh.triangles[t];
            TriangleHit hit;
            if (intersectTriangle(ray, mesh.positions[tri.x], mesh.positions[tri.y], mesh.positions[tri.z], 0.0f, tMax, hit)) {
                tMax = hit.t;
                best = RayHit{hit.t, hit.u, hit.v, static_cast<std::int32_t>(i), -1, static_cast<std::int32_t>(t)};
            }
        }
    }
    return best;
}

} // namespace glint::bvh::test
