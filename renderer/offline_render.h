#pragma once
// Headless rendering for the command line, tests and benchmarks: a scene and a request in, linear
// radiance, AOVs and a tonemapped sRGB image out. Images are rows top-down, RGBA interleaved.
#include "renderer/frame_renderer.h"
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
    Configuration configuration = Configuration::Accumulate;
    int frames = 1;                       // real-time configurations: frames of history (static view)
    int width = 640;
    int height = 360;
    int spp = 16;                         // Accumulate/Reference: in all; real-time: per frame
    std::uint32_t seed = 0;
    int bounces = 4;
    std::string cameraName;               // empty: the project's active camera, else the first one
    float exposure = 0.0f;                // EV added to the camera's
    // Seconds: node animations and camera paths are posed at this time. The scene passed may
    // already be posed at it (posing twice at one time changes nothing).
    double time = 0.0;
    // Motion blur (Accumulate and Reference): samples spread evenly over this many seconds centred on
    // `time`, each path at one instant of it; 0, or a scene where nothing moves: none.
    double shutterSeconds = 0.0;
    std::optional<Tonemapper> tonemapper; // unset: the project's
    std::filesystem::path envFile;        // overrides the project's environment image
    std::filesystem::path sceneFolder;    // resolves the project's relative environment path
    bool requireGpu = false;
    float clamp = 0.0f;                   // 0 = off (unbiased)
    int sampleBlock = 1;                  // Accumulate/Reference: pixels per side sharing a sample sequence
    bool independentSampler = false;
    // Render only these pixels (top-left origin); outside them the images read back hold nothing
    // meaningful and RenderOutput::window names the valid ones. Unset: the whole image.
    std::optional<ImageWindow> region;
    DebugView view = DebugView::None;
    float aoDistance = 1.0f;              // metres, for DebugView::AmbientOcclusion
    // Area emitters' light found by light sampling and BSDF sampling under MIS, or by one alone (the
    // tests that check the strategies agree).
    AreaLightStrategy areaLightStrategy = AreaLightStrategy::Mis;
    BloomSettings bloom;                  // on the tonemapped outputs; EXR radiance too with bloomLinear
    bool bloomLinear = false;
    // The EXR's render passes (FrameSettings::renderPasses; Accumulate and Reference only, else
    // render() throws). Their motion vectors measure from the scene posed `motionSeconds` before
    // `time` (one frame at the project's fps); 0: no motion.
    bool renderPasses = false;
    double motionSeconds = 0.0;
    // Accumulate and Reference: pixels stop once converged (scene/core/settings.h); with every pixel
    // stopped the render ends before `spp`. threshold 0: off.
    AdaptiveSampling adaptive;
    std::function<void(int done, int total)> progress; // after each sample (real-time: frame); may be empty
};

struct RenderTimings {
    double setupMs = 0.0;      // scene upload and shader compilation
    double renderMs = 0.0;     // all samples, finished on the GPU
    double msPerSample = 0.0;  // per sample taken (adaptive sampling may end before spp)
    int samplesTaken = 0;      // Accumulate/Reference: samples in the mean of the pixels that never stopped
};

// FrameImages plus where and how long. variance: unbiased sample variance of one sample's radiance
// (divide by spp for the mean's).
struct RenderOutput : FrameImages {
    std::string glRenderer;
    RenderTimings timings;
    Warnings warnings; // the GPU scene's (textures); `file` empty: the caller names the scene
};

// Owns a headless context and a FrameRenderer in it, so many renders share their setup cost (the
// compiled programs). Every render goes through FrameRenderer: one code path with the editor.
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

// The environment image a request renders with: --env, else the project's (relative to the scene).
std::filesystem::path environmentPath(const Scene& scene, const RenderRequest& request);
// The FrameRenderer settings of a request, with `sppPerFrame` samples per frame (0: the
// configuration's own).
FrameSettings frameSettingsFor(const RenderRequest& request, int sppPerFrame);

// One render with a context of its own.
RenderOutput renderOffline(const Scene& scene, const RenderRequest& request);

} // namespace glint::renderer
