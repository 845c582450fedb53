// Texture timings (a program, not a test): ms per sample at 512x512 for the bundled WaterBottle
// (four 2048^2 textures: base colour, metallic-roughness, normal, emissive) and for the same model
// with its textures removed, so the difference is what texturing costs; medians of 5 runs, each set
// after a warm-up that compiles the shader variant. Also the scene upload time (decoding, CPU mips).
// Usage: bench_textures [spp]  (default 8). Prints a Markdown table.
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
    double setupMs;
};

Timing median(renderer::OfflineRenderer& renderer, const Scene& scene, int spp) {
    renderer::RenderRequest request;
    request.width = 512;
    request.height = 512;
    request.spp = spp;
    request.bounces = 4;
    renderer.render(scene, request); // warm-up: shader compilation
    std::vector<double> ms, setup;
    for (int i = 0; i < 5; ++i) {
        const auto out = renderer.render(scene, request);
        ms.push_back(out.timings.msPerSample);
        setup.push_back(out.timings.setupMs);
    }
    std::sort(ms.begin(), ms.end());
    std::sort(setup.begin(), setup.end());
    return {ms[2], setup[2]};
}

} // namespace

int main(int argc, char** argv) {
    const int spp = argc > 1 ? std::max(1, std::stoi(argv[1])) : 8;
    renderer::OfflineRenderer renderer;
    std::printf("GL_RENDERER: %s; 512x512, %d spp per run, 4 bounces, median of 5 runs\n\n", renderer.glRenderer().c_str(), spp);
    std::printf("| scene | ms/sample | Mpaths/s | upload + setup ms |\n|---|---|---|---|\n");
    for (const bool textured : {true, false}) {
        const Timing t = median(renderer, bottle(textured), spp);
        std::printf("| WaterBottle, %s | %.1f | %.2f | %.0f |\n", textured ? "textured" : "textures removed", t.msPerSample,
                    512.0 * 512.0 / t.msPerSample / 1000.0, t.setupMs);
    }
    return 0;
}
