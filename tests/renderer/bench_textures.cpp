// Texture timings (a program, not a test): ms per sample at 512x512 for the bundled WaterBottle
// (four 2048^2 textures: base colour, metallic-roughness, normal, emissive) and for the same model
// with its textures removed; medians of 5 runs, each set after a warm-up that compiles the shader
// variant. With 4 bounces the two differ in path length too (the untextured bottle is a white rough
// metal, paths survive Russian roulette longer); with 0 bounces every path has the same rays, so the
// difference is what texturing costs. Wall and process CPU time (llvmpipe's threads included: the
// steadier figure on a shared machine; a 1-spp render's CPU time is subtracted, which removes the
// upload), and the scene upload time (decoding, CPU mips).
// Usage: bench_textures [spp]  (default 8). Prints a Markdown table.
#include "scene_builder.h"

#include "renderer/offline_render.h"
#include "scene/io/scene_io.h"

#include <algorithm>
#include <ctime>
#include <cstdio>
#include <string>
#include <vector>

using namespace glint;
using namespace glint::test;

namespace {

Scene bottle(bool textured) {
    Scene scene = loadScene(std::filesystem::path(GLINT_RESOURCES_DIR) / "scenes" / "water_bottle" / "WaterBottle.gltf").scene;
    if (!textured)
        for (auto& [id, m] : scene.materials) m.baseColorTexture = m.metallicRoughnessTexture = m.normalTexture = m.emissiveTexture = TextureRef{};
    scene.settings.environment.color = glm::vec3(0.8f);
    addShape(scene, ShapeKind::GroundPlane, scene.materials.add(lambert(glm::vec3(0.5f))), {0.0f, -0.66f, 0.0f});
    addSun(scene, glm::normalize(glm::vec3(-1.0f, -1.0f, -1.0f)), 2000.0f);
    addPerspectiveCamera(scene, {0.0f, 0.2f, 2.5f}, glm::vec3(0.0f), 0.8f);
    return scene;
}

struct Timing {
    double msPerSample;
    double cpuMsPerSample; // process CPU time per sample: (CPU of spp samples - CPU of 1) / (spp - 1)
    double setupMs;
};

double medianOf(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

Timing median(renderer::OfflineRenderer& renderer, const Scene& scene, int spp, int bounces) {
    renderer::RenderRequest request;
    request.width = 512;
    request.height = 512;
    request.spp = spp;
    request.bounces = bounces;
    renderer.render(scene, request); // warm-up: shader compilation
    renderer::RenderRequest one = request;
    one.spp = 1;
    const auto cpuMs = [&](const renderer::RenderRequest& r, renderer::RenderOutput& out) {
        const std::clock_t start = std::clock();
        out = renderer.render(scene, r);
        return 1000.0 * static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    };
    std::vector<double> ms, cpu, setup;
    for (int i = 0; i < 5; ++i) {
        renderer::RenderOutput out, single;
        const double all = cpuMs(request, out);
        cpu.push_back((all - cpuMs(one, single)) / std::max(spp - 1, 1));
        ms.push_back(out.timings.msPerSample);
        setup.push_back(out.timings.setupMs);
    }
    return {medianOf(ms), medianOf(cpu), medianOf(setup)};
}

} // namespace

int main(int argc, char** argv) {
    const int spp = argc > 1 ? std::max(1, std::stoi(argv[1])) : 8;
    renderer::OfflineRenderer renderer;
    std::printf("GL_RENDERER: %s; 512x512, %d spp per run, median of 5 runs\n\n", renderer.glRenderer().c_str(), spp);
    std::printf("| scene | bounces | ms/sample | CPU ms/sample | Mpaths/s | upload + setup ms |\n|---|---|---|---|---|---|\n");
    for (const int bounces : {4, 0})
        for (const bool textured : {true, false}) {
            const Timing t = median(renderer, bottle(textured), spp, bounces);
            std::printf("| WaterBottle, %s | %d | %.1f | %.1f | %.2f | %.0f |\n", textured ? "textured" : "textures removed", bounces,
                        t.msPerSample, t.cpuMsPerSample, 512.0 * 512.0 / t.msPerSample / 1000.0, t.setupMs);
        }
    return 0;
}
