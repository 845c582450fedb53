#include "ray_count.h"

#include "renderer/bvh/bvh_layout.h"
#include "renderer/bvh/ray_offset.h"
#include "renderer/bvh/traverse.h"
#include "renderer/gpu_scene/camera_setup.h"
#include "renderer/gpu_scene/mesh_data.h"
#include "renderer/gpu_scene/prepared_scene.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

namespace glint::bench {
namespace {

constexpr int kRouletteStart = 3; // integrator.glsl ROULETTE_START

struct Walk {
    const renderer::MeshData& data;
    std::vector<float> survival; // per renderer material index: max component of the base colour
    int lightsPerVertex = 0;     // punctual lights and a sampled environment
    bool endsAtLightSamples = false; // the last vertex casts no closest-hit ray (the bench's surfaces are rough)
    std::mt19937 rng{12345u};
    RayCount count;

    float uniform() { return std::uniform_real_distribution<float>(0.0f, 1.0f)(rng); }
};

struct SurfaceHit {
    glm::vec3 position;
    glm::vec3 normal; // geometric, unit, facing the arriving ray
    std::uint32_t material = 0;
};

// The hit triangle's geometric normal in world space: the instance rows hold localFromWorld, so the
// normal transforms by its transpose.
SurfaceHit surfaceAt(const Walk& w, const bvh::Ray& ray, const bvh::RayHit& hit) {
    const auto& instances = w.data.flat.instances;
    const std::size_t base = bvh::kInstanceTexels * static_cast<std::size_t>(hit.instance);
    glm::mat3 localFromWorld;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) localFromWorld[c][r] = glm::uintBitsToFloat(instances[base + r][c]);
    // The instance names its mesh by its index.
    const bvh::MeshTriangles& mesh = w.data.bvhs.at(instances[base + 3].y).triangles;
    const glm::uvec3 t = mesh.triangles.at(static_cast<std::size_t>(hit.triangle));
    const glm::vec3 local = glm::cross(mesh.positions[t.y] - mesh.positions[t.x], mesh.positions[t.z] - mesh.positions[t.x]);
    glm::vec3 n = glm::normalize(glm::transpose(localFromWorld) * local);
    if (glm::dot(n, ray.direction) > 0.0f) n = -n;
    return {ray.origin + hit.t * ray.direction, n, mesh.materials.at(static_cast<std::size_t>(hit.triangle))};
}

glm::vec3 sampleLightPoint(Walk& w) {
    const renderer::EmissiveTriangles& lights = w.data.lights;
    const float u = w.uniform();
    const auto it = std::upper_bound(lights.cdf.begin(), lights.cdf.end(), u);
    const std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - lights.cdf.begin() - 1, 0)),
                                                static_cast<std::size_t>(lights.count() - 1));
    float a = w.uniform(), b = w.uniform();
    if (a + b > 1.0f) a = 1.0f - a, b = 1.0f - b;
    const std::size_t first = renderer::EmissiveTriangles::texelsPerTriangle * i;
    const glm::vec3 p0(lights.texels[first]), p1(lights.texels[first + 1]), p2(lights.texels[first + 2]);
    return p0 + a * (p1 - p0) + b * (p2 - p0);
}

glm::vec3 cosineDirection(Walk& w, const glm::vec3& n) {
    const float r = std::sqrt(w.uniform()), phi = 6.2831853f * w.uniform();
    const glm::vec3 t = glm::normalize(std::abs(n.x) > 0.5f ? glm::cross(n, glm::vec3(0, 1, 0)) : glm::cross(n, glm::vec3(1, 0, 0)));
    const glm::vec3 b = glm::cross(n, t);
    return glm::normalize(r * std::cos(phi) * t + r * std::sin(phi) * b + std::sqrt(std::max(0.0f, 1.0f - r * r)) * n);
}

// Shadow rays of one vertex: the emissive-triangle sample when it lies on the lit side.
void directLight(Walk& w, const SurfaceHit& s) {
    w.count.shadowRays += static_cast<std::uint64_t>(w.lightsPerVertex);
    if (w.data.lights.count() == 0) return;
    const glm::vec3 toLight = sampleLightPoint(w) - s.position;
    if (!(glm::dot(toLight, s.normal) > 0.0f)) return; // the BSDF is zero there: no ray is cast
    ++w.count.shadowRays;
    bvh::occluded(w.data.flat, {bvh::offsetRayOrigin(s.position, s.normal), toLight}, 1.0f - 1e-4f);
}

void tracePath(Walk& w, bvh::Ray ray, int bounces) {
    ++w.count.paths;
    for (int depth = 0; depth <= bounces + 1; ++depth) {
        ++w.count.closestRays;
        const bvh::RayHit hit = bvh::intersectClosest(w.data.flat, ray, 1e30f);
        if (!hit.hit() || depth > bounces) return;
        const SurfaceHit s = surfaceAt(w, ray, hit);
        directLight(w, s);
        if (depth == bounces && w.endsAtLightSamples) return;
        const float survive = w.survival.at(s.material);
        if (survive <= 0.0f) return;
        if (depth >= kRouletteStart && w.uniform() >= std::min(survive, 0.95f)) return;
        ray = {bvh::offsetRayOrigin(s.position, s.normal), cosineDirection(w, s.normal)};
    }
}

std::vector<float> survivalByIndex(const Scene& scene, std::map<MaterialId, int>& index) {
    std::vector<float> survival{1.0f}; // index 0: glTF's default material (white)
    for (const auto& [id, material] : scene.materials) {
        index[id] = static_cast<int>(survival.size());
        const glm::vec3 c(material.baseColorFactor);
        survival.push_back(std::max({c.x, c.y, c.z}));
    }
    return survival;
}

int lightsPerVertex(const Scene& scene) {
    int lights = 0;
    for (const NodeId id : scene.depthFirst())
        if (scene.at(id).get<Light>()) ++lights;
    return lights + (scene.settings.environment.file.empty() ? 0 : 1);
}

} // namespace

RayCount countRays(const Scene& scene, int width, int height, int bounces, int pathsPerPixel) {
    std::map<MaterialId, int> materialIndex;
    std::vector<float> survival = survivalByIndex(scene, materialIndex);
    renderer::MeshBvhCache cache;
    const renderer::MeshData data = renderer::buildMeshData(scene, materialIndex, false, cache);
    Walk walk{data, std::move(survival), lightsPerVertex(scene), renderer::lightSamplingReachesEveryEmitter(scene, nullptr, !scene.settings.environment.file.empty()),
              std::mt19937(12345u), RayCount{}};
    const renderer::CameraSetup camera = renderer::resolveCamera(scene, "", width, height);
    const glm::vec3 eye(camera.worldFromCamera[3]);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int s = 0; s < pathsPerPixel; ++s) {
                const float u = 2.0f * (static_cast<float>(x) + walk.uniform()) / static_cast<float>(width) - 1.0f;
                const float v = 1.0f - 2.0f * (static_cast<float>(y) + walk.uniform()) / static_cast<float>(height);
                const glm::vec3 local(u * camera.halfExtent.x, v * camera.halfExtent.y, -1.0f);
                tracePath(walk, {eye, glm::normalize(glm::vec3(camera.worldFromCamera * glm::vec4(local, 0.0f)))}, bounces);
            }
    return walk.count;
}

} // namespace glint::bench
