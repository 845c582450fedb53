// Path-tracer timings (a program, not a test): ms per sample and camera paths per second for the
// sphere studio and the Cornell box at 128x128 and 512x512; medians of 5 runs, each after a warm-up.
// Usage: bench_path_tracer [spp]  (default 16). Prints a Markdown table.
#include "scene_builder.h"

#include "renderer/offline_render.h"
#include "scene/io/scene_io.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

using namespace glint;
using namespace glint::test;

namespace {

Scene sphereStudio() {
    Scene scene;
    scene.settings.environment.color = {0.3f, 0.4f, 0.5f};
    const MaterialId ground = scene.materials.add(lambert(glm::vec3(0.7f)));
    const MaterialId red = scene.materials.add(lambert({0.8f, 0.2f, 0.1f}));
    const MaterialId chrome = scene.materials.add(mirror());
    const MaterialId clear = scene.materials.add(glass(1.5f, 0.5f));
    addShape(scene, ShapeKind::GroundPlane, ground, glm::vec3(0.0f));
    addShape(scene, ShapeKind::Sphere, red, {-1.1f, 0.5f, 0.0f});
    addShape(scene, ShapeKind::Sphere, chrome, {0.0f, 0.5f, 0.0f});
    addShape(scene, ShapeKind::Sphere, clear, {1.1f, 0.5f, 0.0f});
    addSun(scene, {0.3f, -1.0f, -0.4f}, 2000.0f, 0.035f);
    addPerspectiveCamera(scene, {0.0f, 1.5f, 4.0f}, {0.0f, 0.4f, 0.0f}, 0.7f);
    return scene;
}

double medianMsPerSample(renderer::OfflineRenderer& renderer, const Scene& scene, int size, int spp) {
    renderer::RenderRequest request;
    request.width = size;
    request.height = size;
    request.spp = spp;
    request.bounces = 4;
    renderer.render(scene, request); // warm-up: shader compilation
    std::vector<double> runs;
    for (int i = 0; i < 5; ++i) runs.push_back(renderer.render(scene, request).timings.msPerSample);
    std::sort(runs.begin(), runs.end());
    return runs[2];
}

} // namespace

int main(int argc, char** argv) {
    const int spp = argc > 1 ? std::max(1, std::stoi(argv[1])) : 16;
    renderer::OfflineRenderer renderer;
    const Scene cornell = loadScene(std::filesystem::path(GLINT_RESOURCES_DIR) / "scenes" / "cornell_box" / "cornell_box.gltf").scene;
    std::printf("GL_RENDERER: %s; %d spp per run, 4 bounces, median of 5 runs\n\n", renderer.glRenderer().c_str(), spp);
    std::printf("| scene | size | ms/sample | Mpaths/s |\n|---|---|---|---|\n");
    const std::pair<const char*, const Scene*> scenes[] = {{"spheres (analytic)", nullptr}, {"Cornell box (BVH)", &cornell}};
    const Scene spheres = sphereStudio();
    for (const auto& [name, scene] : scenes) {
        for (int size : {128, 512}) {
            const double ms = medianMsPerSample(renderer, scene ? *scene : spheres, size, spp);
            std::printf("| %s | %dx%d | %.2f | %.2f |\n", name, size, size, ms, size * size / ms / 1000.0);
        }
    }
    return 0;
}
