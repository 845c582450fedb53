#pragma once
// Headless rendering for the command line, tests and benchmarks: a scene and a request in, linear
// radiance, AOVs and a tonemapped sRGB image out. Images are rows top-down, RGBA interleaved.
#include "renderer/passes/path_trace_pass.h"
#include "scene/core/scene.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace glint::renderer {

struct RenderRequest {
    int width = 640;
    int height = 360;
    int spp = 16;
    std::uint32_t seed = 0;
    int bounces = 4;
    std::string cameraName;               // empty: the project's active camera, else the first one
    float exposure = 0.0f;                // EV added to the camera's
    std::optional<Tonemapper> tonemapper; // unset: the project's
    std::filesystem::path envFile;        // overrides the project's environment image
    std::filesystem::path sceneFolder;    // resolves the project's relative environment path
    bool requireGpu = false;
    float clamp = 0.0f;                   // 0 = off (unbiased)
    bool independentSampler = false;
    DebugView view = DebugView::None;
    float aoDistance = 1.0f;              // metres, for DebugView::AmbientOcclusion
    std::function<void(int done, int total)> progress; // after each sample; may be empty
};

struct RenderTimings {
    double setupMs = 0.0;      // scene upload and shader compilation
    double renderMs = 0.0;     // all samples, finished on the GPU
    double msPerSample = 0.0;
};

struct RenderOutput {
    int width = 0;
    int height = 0;
    std::vector<float> radiance;  // RGBA: linear Rec.709, A = coverage
    std::vector<float> albedo;    // RGB
    std::vector<float> normal;    // XYZ, world space
    std::vector<float> depth;     // along the view axis in metres, +inf where nothing is hit
    std::vector<float> objectId;  // node id, 0 where nothing is hit
    std::vector<float> variance;  // RGB: unbiased sample variance of one sample's radiance (divide by spp for the mean's)
    std::vector<std::uint8_t> tonemapped; // RGBA8, sRGB
    std::string glRenderer;
    RenderTimings timings;
};

// Owns a headless context and compiled programs, so many renders share their setup cost.
class OfflineRenderer {
public:
    explicit OfflineRenderer(bool requireGpu = false);
    ~OfflineRenderer();
    OfflineRenderer(const OfflineRenderer&) = delete;
    OfflineRenderer& operator=(const OfflineRenderer&) = delete;

    // Throws std::runtime_error (or FileError for unreadable inputs) with a one-line reason.
    RenderOutput render(const Scene& scene, const RenderRequest& request);
    const std::string& glRenderer() const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

// One render with a context of its own.
RenderOutput renderOffline(const Scene& scene, const RenderRequest& request);

} // namespace glint::renderer
