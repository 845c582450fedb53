// How long llvmpipe's SIMD groups wait in the BVH walks of a path (a program, not a test), on the
// CPU twin. llvmpipe shades 8 pixels (4x2) per vector and runs a loop until its last lane is done,
// so a group pays for its slowest walk. Traces diffuse paths (camera ray; at each vertex a shadow ray
// to a uniform point of the scene's "light" node and a cosine-sampled continuation; from bounce 3 on
// a path survives with probability 0.75) and counts each walk as the BVH heat map does (nodes +
// primitives). Sums, over the groups, the walk cost of four ways to run them:
//   walk by walk  the shader today: each walk is its own loop, so a group runs its slowest lane's
//                 steps of every walk;
//   paired        a vertex's shadow and continuation walks in one loop;
//   one loop      every walk of a path in one loop (a group runs its slowest lane's whole path);
//   no waiting    each lane's own steps (the mean over a group's lanes).
// Usage: bench_simd_waits OUTPUT_CSV SCENE... (128x128, 4 and 16 bounces, fixed seed)
#include "twin_scene.h"

#include "renderer/bvh/bvh_layout.h"
#include "renderer/bvh/ray_offset.h"
#include "renderer/bvh/traverse.h"
#include "renderer/gpu_scene/camera_setup.h"
#include "scene/io/scene_io.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <string>
#include <vector>

using namespace glint;

namespace {

constexpr int kSize = 128;
constexpr int kGroupWidth = 4, kGroupHeight = 2; // llvmpipe's 8 lanes at 256 bits
constexpr int kRouletteStart = 3;
constexpr float kSurvival = 0.75f;

using Triangle = std::array<glm::vec3, 3>;

glm::vec3 worldCorner(const test::TwinScene& twin, std::size_t instance, std::uint32_t slot, int k) {
    return glm::vec3(twin.worldFrom[instance] * glm::vec4(glm::vec3(twin.flat.trianglePositions[3 * std::size_t(slot) + std::size_t(k)]), 1.0f));
}

std::vector<Triangle> lightTriangles(const test::TwinScene& twin) {
    std::vector<Triangle> light;
    for (std::size_t i = 0; i < twin.names.size(); ++i) {
        if (twin.names[i] != "light") continue;
        const bvh::FlatMeshRange& mesh = twin.flat.meshes[twin.flat.instances[bvh::kInstanceTexels * i + 3].y];
        for (std::uint32_t slot = mesh.firstSlot; slot < mesh.firstSlot + mesh.triangleCount; ++slot)
            light.push_back({worldCorner(twin, i, slot, 0), worldCorner(twin, i, slot, 1), worldCorner(twin, i, slot, 2)});
    }
    return light;
}

int costOf(const bvh::TraversalCost& c) { return c.nodes + c.primitives; }

// One path's walk costs: the camera ray's, then per vertex its shadow walk and its continuation's.
struct PathCosts {
    int camera = 0;
    std::vector<int> shadow, continuation; // per vertex, 0 where none was traced
};

class PathTracer {
public:
    PathTracer(const Scene& scene, const test::TwinScene& twin, int bounces)
        : twin_(twin), light_(lightTriangles(twin)), camera_(renderer::resolveCamera(scene, "", kSize, kSize)), bounces_(bounces) {}

    PathCosts trace(int x, int y) {
        PathCosts costs;
        costs.shadow.assign(std::size_t(bounces_ + 1), 0);
        costs.continuation.assign(std::size_t(bounces_ + 1), 0);
        const glm::vec2 ndc((float(x) + uniform()) / float(kSize) * 2.0f - 1.0f, 1.0f - (float(y) + uniform()) / float(kSize) * 2.0f);
        glm::vec3 origin(camera_.worldFromCamera[3]);
        glm::vec3 direction = glm::normalize(glm::vec3(camera_.worldFromCamera * glm::vec4(ndc * camera_.halfExtent, -1.0f, 0.0f)));
        bvh::TraversalCost cost;
        bvh::RayHit hit = bvh::intersectClosest(twin_.flat, {origin, direction}, INFINITY, nullptr, &cost);
        costs.camera = costOf(cost);
        for (int depth = 0; depth <= bounces_ && hit.instance >= 0 && twin_.names[std::size_t(hit.instance)] != "light"; ++depth) {
            const glm::vec3 normal = facing(hit, direction);
            const glm::vec3 p = bvh::offsetRayOrigin(origin + hit.t * direction, normal);
            costs.shadow[std::size_t(depth)] = shadowCost(p, normal);
            if (depth == bounces_ || (depth >= kRouletteStart && uniform() >= kSurvival)) break;
            origin = p;
            direction = cosineDirection(normal);
            bvh::TraversalCost next;
            hit = bvh::intersectClosest(twin_.flat, {origin, direction}, INFINITY, nullptr, &next);
            costs.continuation[std::size_t(depth)] = costOf(next);
        }
        return costs;
    }

private:
    float uniform() { return uniform_(random_); }

    glm::vec3 facing(const bvh::RayHit& hit, const glm::vec3& direction) const {
        const glm::vec3 n = test::hitNormal(twin_, hit);
        return glm::dot(n, direction) > 0.0f ? -n : n;
    }

    int shadowCost(const glm::vec3& p, const glm::vec3& normal) {
        if (light_.empty()) return 0;
        const Triangle& t = light_[std::min(light_.size() - 1, std::size_t(uniform() * float(light_.size())))];
        const float su = std::sqrt(uniform()), v = uniform();
        const glm::vec3 q = (1.0f - su) * t[0] + v * su * t[1] + (su - v * su) * t[2];
        glm::vec3 lightNormal = glm::normalize(glm::cross(t[1] - t[0], t[2] - t[0]));
        if (glm::dot(lightNormal, p - q) < 0.0f) lightNormal = -lightNormal;
        const glm::vec3 towards = bvh::offsetRayOrigin(q, lightNormal) - p;
        const float distance = glm::length(towards);
        if (!(distance > 0.0f) || glm::dot(towards, normal) <= 0.0f) return 0;
        bvh::TraversalCost cost;
        bvh::occluded(twin_.flat, {p, towards / distance}, distance, nullptr, &cost);
        return costOf(cost);
    }

    glm::vec3 cosineDirection(const glm::vec3& n) {
        const glm::vec3 t = glm::normalize(std::abs(n.x) > 0.5f ? glm::cross(n, glm::vec3(0, 1, 0)) : glm::cross(n, glm::vec3(1, 0, 0)));
        const glm::vec3 b = glm::cross(n, t);
        const float r = std::sqrt(uniform()), phi = 2.0f * std::numbers::pi_v<float> * uniform();
        return r * std::cos(phi) * t + r * std::sin(phi) * b + std::sqrt(std::max(0.0f, 1.0f - r * r)) * n;
    }

    const test::TwinScene& twin_;
    std::vector<Triangle> light_;
    renderer::CameraSetup camera_;
    int bounces_;
    std::mt19937 random_{1}; // fixed: the figures repeat
    std::uniform_real_distribution<float> uniform_{0.0f, 1.0f};
};

struct Totals {
    double walkByWalk = 0, paired = 0, oneLoop = 0, noWaiting = 0;
};

// A group's cost each way; `lanes`: its pixels' paths.
void addGroup(const std::vector<PathCosts>& lanes, Totals& totals) {
    int camera = 0, wholeSlowest = 0;
    double own = 0;
    std::vector<int> whole(lanes.size(), 0);
    for (std::size_t l = 0; l < lanes.size(); ++l) {
        camera = std::max(camera, lanes[l].camera);
        own += lanes[l].camera;
    }
    totals.walkByWalk += camera;
    totals.paired += camera;
    for (std::size_t v = 0; v < lanes[0].shadow.size(); ++v) {
        int shadow = 0, continuation = 0, both = 0;
        for (std::size_t l = 0; l < lanes.size(); ++l) {
            const int s = lanes[l].shadow[v], c = lanes[l].continuation[v];
            shadow = std::max(shadow, s);
            continuation = std::max(continuation, c);
            both = std::max(both, s + c);
            whole[l] += s + c;
            own += s + c;
        }
        totals.walkByWalk += shadow + continuation;
        totals.paired += both;
    }
    for (std::size_t l = 0; l < lanes.size(); ++l) wholeSlowest = std::max(wholeSlowest, lanes[l].camera + whole[l]);
    totals.oneLoop += wholeSlowest;
    totals.noWaiting += own / double(lanes.size());
}

Totals measure(const Scene& scene, const test::TwinScene& twin, int bounces) {
    PathTracer tracer(scene, twin, bounces);
    std::vector<PathCosts> paths;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) paths.push_back(tracer.trace(x, y));
    Totals totals;
    for (int gy = 0; gy < kSize; gy += kGroupHeight)
        for (int gx = 0; gx < kSize; gx += kGroupWidth) {
            std::vector<PathCosts> lanes;
            for (int j = 0; j < kGroupHeight; ++j)
                for (int i = 0; i < kGroupWidth; ++i) lanes.push_back(paths[std::size_t((gy + j) * kSize + gx + i)]);
            addGroup(lanes, totals);
        }
    return totals;
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: bench_simd_waits OUTPUT_CSV SCENE...\n");
        return 2;
    }
    std::ofstream csv(argv[1]);
    csv << "scene,bounces,walk_by_walk,paired,one_loop,no_waiting\n";
    std::printf("| scene | bounces | walk by walk | paired | one loop | no waiting |\n|---|---|---|---|---|---|\n");
    for (int i = 2; i < argc; ++i) {
        const Scene scene = loadScene(argv[i]).scene;
        const test::TwinScene twin = test::twinScene(scene);
        const std::string name = std::filesystem::path(argv[i]).stem().string();
        for (int bounces : {4, 16}) {
            const Totals t = measure(scene, twin, bounces);
            csv << name << ',' << bounces << ',' << t.walkByWalk << ',' << t.paired << ',' << t.oneLoop << ',' << t.noWaiting << '\n';
            std::printf("| %s | %d | %.0f | %.0f (%.2f) | %.0f (%.2f) | %.0f (%.2f) |\n", name.c_str(), bounces, t.walkByWalk, t.paired,
                        t.paired / t.walkByWalk, t.oneLoop, t.oneLoop / t.walkByWalk, t.noWaiting, t.noWaiting / t.walkByWalk);
        }
    }
    return csv ? 0 : 1;
}
