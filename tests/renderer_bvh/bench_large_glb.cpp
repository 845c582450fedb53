// A large GLB for load-to-pixel timings (a program, not a test): an icosphere subdivided
// SUBDIVISIONS times (20 * 4^n triangles; Blender's "subdivisions 8" is n = 7: 327,680), COPIES
// copies of it in a row along x merged into one mesh (as Blender's Array modifier exports them:
// 4 copies of n = 7 make 1,310,720 triangles), smooth normals and spherical UVs, a grey material, a
// sun and a camera. Written with Glint's own scene code and glTF writer, so the repository holds
// no large file. With --stages it then reads the file back and times the CPU stages one after the
// other in this process (read, mesh data with BVHs, validation), to set beside `glint render`.
//
// Usage: bench_large_glb OUTPUT_DIR [--subdivisions N] [--copies N] [--stages]
//        writes OUTPUT_DIR/icospheres.glb and prints its triangle count and size.
#include "renderer/bvh/validate.h"
#include "renderer/gpu_scene/mesh_data.h"
#include "renderer/gpu_scene/packed_scene.h"
#include "scene/core/scene.h"
#include "scene/io/scene_io.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/quaternion.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <string>
#include <unordered_map>
#include <vector>

using namespace glint;

namespace {

struct Sphere {
    std::vector<glm::vec3> positions; // on the unit sphere
    std::vector<std::uint32_t> indices;
};

// The icosahedron, each triangle split in four `subdivisions` times, new vertices pushed out to
// the sphere (shared between neighbours: the mesh is closed).
Sphere icosphere(int subdivisions)
{
    const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
    Sphere s;
    for (const glm::vec3 p : {glm::vec3(-1, t, 0), glm::vec3(1, t, 0), glm::vec3(-1, -t, 0), glm::vec3(1, -t, 0), glm::vec3(0, -1, t),
                              glm::vec3(0, 1, t), glm::vec3(0, -1, -t), glm::vec3(0, 1, -t), glm::vec3(t, 0, -1), glm::vec3(t, 0, 1),
                              glm::vec3(-t, 0, -1), glm::vec3(-t, 0, 1)})
        s.positions.push_back(glm::normalize(p));
    s.indices = {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4, 11, 10, 2, 10, 7, 6, 7, 1, 8,
                 3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1};
    for (int level = 0; level < subdivisions; ++level) {
        std::unordered_map<std::uint64_t, std::uint32_t> midpoints; // looked up only, never iterated
        const auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
            const std::uint64_t key = (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
            const auto [it, inserted] = midpoints.try_emplace(key, static_cast<std::uint32_t>(s.positions.size()));
            if (inserted) s.positions.push_back(glm::normalize(s.positions[a] + s.positions[b]));
            return it->second;
        };
        std::vector<std::uint32_t> next;
        next.reserve(4 * s.indices.size());
        for (std::size_t i = 0; i < s.indices.size(); i += 3) {
            const std::uint32_t a = s.indices[i], b = s.indices[i + 1], c = s.indices[i + 2];
            const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
            next.insert(next.end(), {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca});
        }
        s.indices = std::move(next);
    }
    return s;
}

Scene icosphereRow(int subdivisions, int copies)
{
    const Sphere sphere = icosphere(subdivisions);
    Primitive p;
    std::vector<glm::vec3> positions, normals;
    std::vector<glm::vec2> uvs;
    std::vector<std::uint32_t> indices;
    for (int copy = 0; copy < copies; ++copy) {
        const auto base = static_cast<std::uint32_t>(positions.size());
        const glm::vec3 offset(2.5f * static_cast<float>(copy) - 1.25f * static_cast<float>(copies - 1), 1.0f, 0.0f);
        for (const glm::vec3& n : sphere.positions) {
            positions.push_back(offset + n);
            normals.push_back(n);
            uvs.emplace_back(0.5f + std::atan2(n.x, n.z) / glm::two_pi<float>(), std::acos(std::clamp(n.y, -1.0f, 1.0f)) / glm::pi<float>());
        }
        for (const std::uint32_t i : sphere.indices) indices.push_back(base + i);
    }
    p.positions = std::move(positions);
    p.normals = std::move(normals);
    p.uv0 = std::move(uvs);
    p.indices = std::move(indices);

    Scene scene;
    Material grey;
    grey.name = "grey";
    grey.baseColorFactor = glm::vec4(0.6f, 0.6f, 0.6f, 1.0f);
    grey.roughnessFactor = 0.5f;
    grey.metallicFactor = 0.0f;
    p.material = scene.materials.add(grey);
    Mesh mesh;
    mesh.name = "Icosphere";
    mesh.primitives.push_back(std::move(p));
    Node spheres;
    spheres.name = "Icosphere";
    spheres.component = MeshInstance{scene.meshes.add(std::move(mesh))};
    scene.addNode(std::move(spheres));

    Node sun;
    sun.name = "Sun";
    sun.local.rotation = glm::angleAxis(-0.9f, glm::vec3(1.0f, 0.0f, 0.0f)) * glm::angleAxis(0.5f, glm::vec3(0.0f, 1.0f, 0.0f));
    Light light;
    light.type = LightType::Sun;
    light.intensity = 2000.0f; // lux: about 2.9 W/m^2 as Blender reads it (docs/LIGHTS.md)
    sun.component = light;
    scene.addNode(std::move(sun));

    Node camera;
    camera.name = "Camera";
    const float distance = 3.0f * static_cast<float>(copies) + 2.0f;
    camera.local.translation = glm::vec3(0.0f, 1.0f + 0.35f * distance, distance);
    camera.local.rotation = glm::angleAxis(-0.33f, glm::vec3(1.0f, 0.0f, 0.0f));
    camera.component = Camera{};
    scene.addNode(std::move(camera));
    return scene;
}

struct Stopwatch {
    std::chrono::steady_clock::time_point wall = std::chrono::steady_clock::now();
    std::clock_t cpu = std::clock();
    void print(const char* what) const
    {
        const double wallMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - wall).count();
        const double cpuMs = 1000.0 * static_cast<double>(std::clock() - cpu) / CLOCKS_PER_SEC;
        std::printf("%-32s %9.1f ms wall %9.1f ms CPU\n", what, wallMs, cpuMs);
    }
};

void timeStages(const std::filesystem::path& file)
{
    Stopwatch load;
    const LoadResult loaded = loadScene(file);
    load.print("read the GLB (loadScene)");
    Stopwatch pack;
    const renderer::PackedScene packed = renderer::packScene(loaded.scene);
    pack.print("pack materials and lights");
    renderer::MeshBvhCache cache;
    Stopwatch meshes;
    const renderer::MeshData data = renderer::buildMeshData(loaded.scene, packed.materialIndex, false, cache);
    meshes.print("mesh data (BVHs, top level, flat)");
    Stopwatch validate;
    const auto problem = bvh::validateFlatScene(data.flat);
    validate.print(problem ? problem->c_str() : "validate the flattened BVH");
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 2) {
        std::fprintf(stderr, "usage: bench_large_glb OUTPUT_DIR [--subdivisions N] [--copies N] [--stages]\n");
        return 2;
    }
    int subdivisions = 7, copies = 4;
    bool stages = false;
    for (int i = 2; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--subdivisions" && i + 1 < argc) subdivisions = std::stoi(argv[++i]);
        else if (arg == "--copies" && i + 1 < argc) copies = std::stoi(argv[++i]);
        else if (arg == "--stages") stages = true;
        else {
            std::fprintf(stderr, "bench_large_glb: unknown argument '%s'\n", arg.c_str());
            return 2;
        }
    }
    const std::filesystem::path dir = argv[1];
    std::filesystem::create_directories(dir);
    const std::filesystem::path file = dir / "icospheres.glb";
    const Scene scene = icosphereRow(subdivisions, copies);
    saveScene(scene, file, SaveOptions{false, {}});
    std::printf("%s: %zu triangles, %.1f MB\n", file.string().c_str(), scene.meshes.begin()->second.triangleCount(),
                static_cast<double>(std::filesystem::file_size(file)) / 1e6);
    if (stages) timeStages(file);
    return 0;
}
