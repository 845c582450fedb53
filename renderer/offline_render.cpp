#include "renderer/offline_render.h"

#include "renderer/gl/headless_context.h"
#include "renderer/passes/adaptive_sampling.h"
#include "scene/anim/scene_at_time.h"
#include "scene/io/project/project_file.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <numeric>
#include <stdexcept>

namespace glint::renderer {

struct OfflineRenderer::State {
    explicit State(bool requireGpu) : context(gl::HeadlessContextOptions{requireGpu}) {}
    gl::HeadlessContext context;
    FrameRenderer frames; // destroyed before the context
};

namespace {

using Clock = std::chrono::steady_clock;

// The instant of sample i of a motion-blurred still: the spp samples take the centres of spp equal
// parts of the shutter interval, each part once (a stratified set, so a moving edge blurs to an
// even ramp at any spp), visited in an order that strides through the interval (i x a step coprime
// with spp), so the first samples already span it and the order is not the sampler's own.
double shutterInstant(const RenderRequest& request, int i) {
    const auto n = static_cast<std::uint64_t>(std::max(1, request.spp));
    std::uint64_t step = std::max<std::uint64_t>(1, n * 5 / 8);
    while (std::gcd(step, n) != 1) ++step;
    const double part = double((std::uint64_t(i) * step) % n);
    return request.time + request.shutterSeconds * ((part + 0.5) / double(n) - 0.5);
}

double millisecondsSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

void validate(const RenderRequest& request) {
    if (request.width <= 0 || request.height <= 0) throw std::runtime_error("the image size must be positive");
    if (request.spp <= 0) throw std::runtime_error("samples per pixel must be at least 1");
    if (request.bounces < 0) throw std::runtime_error("bounces must be 0 or more");
    if (request.frames <= 0) throw std::runtime_error("frames must be at least 1");
    if (const auto& r = request.region;
        r && (r->x < 0 || r->y < 0 || r->width < 1 || r->height < 1 || r->x + r->width > request.width ||
              r->y + r->height > request.height))
        throw std::runtime_error("the render region must be a non-empty part of the image");
    if (!(request.adaptive.threshold >= 0.0f && request.adaptive.threshold <= 1.0f) || request.adaptive.minSamples < 0)
        throw std::runtime_error("the adaptive sampling threshold must be 0 (off) to 1 and its minimum samples 0 or more");
    if (request.renderPasses && !traitsOf(request.configuration).accumulate)
        throw std::runtime_error("render passes need the accumulate or reference configuration");
}

} // namespace

std::filesystem::path environmentPath(const Scene& scene, const RenderRequest& request) {
    if (!request.envFile.empty()) return request.envFile;
    const std::string& file = scene.settings.environment.file;
    if (file.empty()) return {};
    // The project's path was checked at load; checked again here, where it is opened, so a symlink
    // swapped since then or a path set after the load cannot lead out of the scene's folder.
    const std::string folder = request.sceneFolder.empty() ? std::string(".") : request.sceneFolder.string();
    return projectEnvironmentPath(request.sceneFolder, file, folder);
}

FrameSettings frameSettingsFor(const RenderRequest& request, int sppPerFrame) {
    FrameSettings s;
    s.configuration = request.configuration;
    s.spp = sppPerFrame;
    s.bounces = request.bounces;
    s.seed = request.seed;
    s.exposure = request.exposure;
    s.tonemapper = request.tonemapper;
    s.view = request.view;
    s.clamp = request.clamp;
    s.sampleBlock = request.sampleBlock;
    s.bloom = request.bloom;
    s.bloomLinear = request.bloomLinear;
    s.renderPasses = request.renderPasses;
    s.adaptive = request.adaptive;
    s.adaptive.minSamples = adaptiveMinSamples(request.adaptive, request.spp);
    s.independentSampler = request.independentSampler;
    s.aoDistance = request.aoDistance;
    s.areaLightStrategy = request.areaLightStrategy;
    s.width = request.width;
    s.height = request.height;
    if (request.region) s.region = regionOfWindow(*request.region, request.width, request.height);
    return s;
}

OfflineRenderer::OfflineRenderer(bool requireGpu)
    : state_(std::make_unique<State>(requireGpu)) {}

OfflineRenderer::~OfflineRenderer() = default;

const std::string& OfflineRenderer::glRenderer() const { return state_->context.renderer(); }

RenderOutput OfflineRenderer::render(const Scene& scene, const RenderRequest& request) {
    validate(request);
    const bool accumulate = traitsOf(request.configuration).accumulate;
    FrameRenderer& frames = state_->frames;
    const auto setupStart = Clock::now();
    frames.setSettings(frameSettingsFor(request, accumulate ? 1 : request.spp)); // accumulation: one sample per frame, for progress
    frames.setCamera(resolveCamera(scene, request.cameraName, request.width, request.height));
    frames.setTime(request.time); // before the scene: setScene poses it at the renderer's time
    frames.setScene(scene, environmentPath(scene, request));
    if (request.renderPasses) {
        // The motion vectors' previous frame: the scene and its camera one frame earlier.
        Scene storage;
        const Scene& previous = request.motionSeconds > 0.0 ? posedAt(scene, request.time - request.motionSeconds, storage) : scene;
        frames.setMotionReference(resolveCamera(previous, request.cameraName, request.width, request.height), previous);
    }
    frames.resetHistory();
    RenderOutput out;
    out.glRenderer = state_->context.renderer();
    out.warnings = frames.warnings();
    out.timings.setupMs = millisecondsSince(setupStart);

    const auto renderStart = Clock::now();
    const int count = accumulate ? request.spp : request.frames;
    const bool blurred = accumulate && request.shutterSeconds > 0.0 && sceneAnimates(scene);
    for (int i = 0; i < count && !frames.converged(); ++i) {
        if (blurred) frames.setShutterTime(shutterInstant(request, i));
        frames.renderFrame();
        if (request.progress) {
            glFinish();
            // Every pixel converged: the samples left are not taken, and the render is done.
            request.progress(frames.converged() ? count : i + 1, count);
        }
    }
    glFinish();
    out.timings.renderMs = millisecondsSince(renderStart);
    out.timings.samplesTaken = accumulate ? frames.sampleCount() : request.spp * request.frames;
    out.timings.msPerSample = out.timings.renderMs / std::max(1, out.timings.samplesTaken);
    static_cast<FrameImages&>(out) = frames.readImages();
    return out;
}

RenderOutput renderOffline(const Scene& scene, const RenderRequest& request) {
    OfflineRenderer renderer(request.requireGpu);
    return renderer.render(scene, request);
}

} // namespace glint::renderer
