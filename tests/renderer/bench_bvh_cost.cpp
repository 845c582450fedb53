// BVH traversal cost of the Cornell box on the CPU twin (a program, not a test): the camera rays
// at the pixel centres and, from each camera hit, cosine-distributed first-bounce rays, walked by
// renderer/bvh/traverse.cpp exactly as shaders/bvh/traverse.glsl walks them and counted as the
// BVH heat map counts (nodes visited over both levels + primitives tested). Prints the mean and
// the largest cost per ray class and per surface the bounce starts on.
// Usage: bench_bvh_cost [SCENE] [size] [bounce rays per pixel]  (default: the Cornell box, 128, 4)
#include "twin_scene.h"

#include "renderer/bvh/bvh_layout.h"
#include "renderer/bvh/ray_offset.h"
#include "renderer/bvh/traverse.h"
#include "renderer/gpu_scene/camera_setup.h"
#include "scene/io/scene_io.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <vector>

using namespace glint;

namespace {

struct Tally {
    long long rays = 0, nodes = 0, primitives = 0, hits = 0;
    int largest = 0;
    void add(const bvh::TraversalCost& c, bool hit) {
        ++rays;
        nodes += c.nodes;
        primitives += c.primitives;
        hits += hit;
        largest = std::max(largest, c.nodes + c.primitives);
    }
    void print(const std::string& name) const {
        const double n = double(std::max(rays, 1LL));
        std::printf("| %s | %lld | %.1f | %.1f | %.1f | %d | %.0f %% |\n", name.c_str(), rays, double(nodes) / n,
                    double(primitives) / n, double(nodes + primitives) / n, largest, 100.0 * double(hits) / n);
    }
};

} // namespace

int main(int argc, char** argv) {
    const std::string file = argc > 1 ? argv[1] : std::string(GLINT_RESOURCES_DIR) + "/scenes/cornell_box/cornell_box.gltf";
    const int size = argc > 2 ? std::stoi(argv[2]) : 128;
    const int bounces = argc > 3 ? std::stoi(argv[3]) : 4;
    const Scene scene = loadScene(file).scene;
    const test::TwinScene twin = test::twinScene(scene);
    const renderer::CameraSetup camera = renderer::resolveCamera(scene, "", size, size);
    std::printf("%s: %zu instances, %zu nodes (%u in mesh BVHs), %zu triangle slots\n", file.c_str(), twin.names.size(),
                twin.flat.nodes.size(), twin.flat.meshNodeCount, twin.flat.trianglePositions.size() / 3);
    std::mt19937 random(1); // fixed: the figures repeat
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    Tally primary, bounce, bounceMiss;
    // A SIMD group of pixels waits for its slowest lane: the largest cost per 4x4 tile, camera rays
    // and the first of each pixel's bounce rays.
    const int tiles = (size + 3) / 4;
    std::vector<int> tileCamera(std::size_t(tiles * tiles), 0), tileBounce(std::size_t(tiles * tiles), 0);
    std::map<std::string, Tally> byStart;
    const glm::vec3 eye(camera.worldFromCamera[3]);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const glm::vec2 ndc((float(x) + 0.5f) / float(size) * 2.0f - 1.0f, 1.0f - (float(y) + 0.5f) / float(size) * 2.0f);
            const glm::vec3 d = glm::normalize(glm::vec3(camera.worldFromCamera * glm::vec4(ndc * camera.halfExtent, -1.0f, 0.0f)));
            bvh::TraversalCost cost;
            const bvh::RayHit hit = bvh::intersectClosest(twin.flat, {eye, d}, INFINITY, nullptr, &cost);
            primary.add(cost, hit.instance >= 0);
            const std::size_t tile = std::size_t((y / 4) * tiles + x / 4);
            tileCamera[tile] = std::max(tileCamera[tile], cost.nodes + cost.primitives);
            if (hit.instance < 0) continue;
            glm::vec3 n = test::hitNormal(twin, hit);
            if (glm::dot(n, d) > 0.0f) n = -n;
            const glm::vec3 p = bvh::offsetRayOrigin(eye + hit.t * d, n);
            const glm::vec3 t = glm::normalize(std::abs(n.x) > 0.5f ? glm::cross(n, glm::vec3(0, 1, 0)) : glm::cross(n, glm::vec3(1, 0, 0)));
            const glm::vec3 b = glm::cross(n, t);
            for (int k = 0; k < bounces; ++k) {
                const float r = std::sqrt(uniform(random)), phi = 2.0f * std::numbers::pi_v<float> * uniform(random);
                const glm::vec3 w = r * std::cos(phi) * t + r * std::sin(phi) * b + std::sqrt(std::max(0.0f, 1.0f - r * r)) * n;
                bvh::TraversalCost c;
                const bvh::RayHit h = bvh::intersectClosest(twin.flat, {p, w}, INFINITY, nullptr, &c);
                bounce.add(c, h.instance >= 0);
                if (k == 0) tileBounce[tile] = std::max(tileBounce[tile], c.nodes + c.primitives);
                if (h.instance < 0) bounceMiss.add(c, false);
                byStart[twin.names[std::size_t(hit.instance)]].add(c, h.instance >= 0);
            }
        }
    std::printf("\n| rays | count | nodes | primitives | cost | largest | hit |\n|---|---|---|---|---|---|---|\n");
    primary.print("camera");
    bounce.print("first bounce");
    bounceMiss.print("first bounce, escaping");
    for (const auto& [name, tally] : byStart) tally.print("first bounce from " + name);
    const auto mean = [](const std::vector<int>& v) { double s = 0; for (int c : v) s += c; return s / double(v.size()); };
    std::printf("\nlargest cost per 4x4 tile, mean over tiles: camera %.1f, first bounce %.1f\n", mean(tileCamera), mean(tileBounce));
    return 0;
}
