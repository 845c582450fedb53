// Texture decode cache timings (a program, not a test) for docs/PERFORMANCE.md: WaterBottle's four
// 2048^2 PNGs. (1) The CPU stage alone, buildTextureSet: decoding + mipmaps without a cache, then
// a rebuild through a warm TextureCache (what is left: hashing and comparing the encoded bytes).
// (2) A full GPU scene rebuild as a host does it (OfflineRenderer -> FrameRenderer::setScene:
// textures, packing, mesh data, upload), the first one cold and the next ones warm. Medians of 5.
// Usage: bench_texture_cache. Prints a Markdown table.
#include "renderer/gpu_scene/texture_set.h"
#include "renderer/offline_render.h"
#include "scene/io/oiio/oiio_image_decoder.h"
#include "scene/io/scene_io.h"
#include "scene_builder.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

using namespace glint;

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) { return std::chrono::duration<double, std::milli>(Clock::now() - start).count(); }

double medianOf(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

double buildMs(const Scene& scene, renderer::TextureCache* cache) {
    const auto start = Clock::now();
    const renderer::TextureSet set = renderer::buildTextureSet(scene, renderer::meshMaterials(scene), OiioImageDecoder{},
                                                               renderer::TextureLimits{}, cache);
    return msSince(start);
}

} // namespace

int main() {
    Scene scene = loadScene(std::filesystem::path(GLINT_RESOURCES_DIR) / "scenes" / "water_bottle" / "WaterBottle.gltf").scene;
    test::addPerspectiveCamera(scene, {0.0f, 0.2f, 2.5f}, glm::vec3(0.0f), 0.8f);

    std::vector<double> cold, warm;
    for (int i = 0; i < 5; ++i) {
        renderer::TextureCache cache;
        cold.push_back(buildMs(scene, &cache));
        warm.push_back(buildMs(scene, &cache));
    }
    std::vector<double> none;
    for (int i = 0; i < 5; ++i) none.push_back(buildMs(scene, nullptr));

    renderer::OfflineRenderer renderer;
    renderer::RenderRequest request;
    request.width = 64;
    request.height = 64;
    request.spp = 1;
    const double firstSetup = renderer.render(scene, request).timings.setupMs;
    std::vector<double> rebuild;
    for (int i = 0; i < 5; ++i) rebuild.push_back(renderer.render(scene, request).timings.setupMs);

    renderer::TextureCache sized;
    buildMs(scene, &sized);
    std::printf("GL_RENDERER: %s; WaterBottle, medians of 5 (ms); cache holds %.1f MiB for it\n\n", renderer.glRenderer().c_str(),
                static_cast<double>(sized.bytes()) / (1024.0 * 1024.0));
    std::printf("| step | no cache | cold cache | warm cache |\n|---|---|---|---|\n");
    std::printf("| buildTextureSet (decode + mipmaps) | %.0f | %.0f | %.1f |\n", medianOf(none), medianOf(cold), medianOf(warm));
    std::printf("| full GPU scene build (FrameRenderer::setScene) | | %.0f (first) | %.0f |\n", firstSetup, medianOf(rebuild));
    return 0;
}
