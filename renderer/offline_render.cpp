#include "renderer/offline_render.h"

#include "renderer/gl/headless_context.h"
#include "renderer/gl/program_cache.h"
#include "renderer/passes/accumulate_pass.h"
#include "renderer/passes/tonemap_pass.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace glint::renderer {

struct OfflineRenderer::State {
    explicit State(bool requireGpu) : context(gl::HeadlessContextOptions{requireGpu}) {}
    gl::HeadlessContext context;
    gl::ProgramCache programs; // destroyed before the context
};

namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

std::filesystem::path environmentPath(const Scene& scene, const RenderRequest& request) {
    if (!request.envFile.empty()) return request.envFile;
    const std::string& file = scene.settings.environment.file;
    return file.empty() ? std::filesystem::path() : request.sceneFolder / file;
}

// GL rows run bottom-up; outputs run top-down. Keeps `channels` of each RGBA texel.
template <class T>
std::vector<T> topDown(const std::vector<T>& rgba, int width, int height, int channels) {
    std::vector<T> out;
    out.reserve(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * static_cast<std::size_t>(channels));
    for (int y = height - 1; y >= 0; --y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < channels; ++c)
                out.push_back(rgba[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 4 + static_cast<std::size_t>(c)]);
    return out;
}

// Per-pixel sample variance n/(n-1) (E[x^2] - E[x]^2), clamped at 0 against rounding.
std::vector<float> sampleVariance(const std::vector<float>& mean, const std::vector<float>& meanSquared, int samples) {
    std::vector<float> variance;
    variance.reserve(mean.size() / 4 * 3);
    const double correction = samples > 1 ? static_cast<double>(samples) / (samples - 1) : 0.0;
    for (std::size_t i = 0; i < mean.size(); i += 4)
        for (std::size_t c = 0; c < 3; ++c)
            variance.push_back(static_cast<float>(
                std::max(0.0, correction * (static_cast<double>(meanSquared[i + c]) - static_cast<double>(mean[i + c]) * mean[i + c]))));
    return variance;
}

void readOutputs(const gl::RenderTarget& mean, const gl::RenderTarget& tonemapped, int samples, RenderOutput& out) {
    const int w = out.width;
    const int h = out.height;
    out.radiance = topDown(mean.readRgba(radianceAttachment), w, h, 4);
    out.albedo = topDown(mean.readRgba(albedoAttachment), w, h, 3);
    const auto normalDepth = topDown(mean.readRgba(normalDepthAttachment), w, h, 4);
    for (std::size_t i = 0; i < normalDepth.size(); i += 4) {
        out.normal.insert(out.normal.end(), normalDepth.begin() + static_cast<std::ptrdiff_t>(i),
                          normalDepth.begin() + static_cast<std::ptrdiff_t>(i + 3));
        out.depth.push_back(normalDepth[i + 3] < 0.0f ? std::numeric_limits<float>::infinity() : normalDepth[i + 3]);
    }
    out.objectId = topDown(mean.readRgba(objectIdAttachment), w, h, 1);
    out.tonemapped = topDown(tonemapped.readRgba8(0), w, h, 4);
    out.variance = sampleVariance(out.radiance, topDown(mean.readRgba(radianceSquaredAttachment), w, h, 4), samples);
}

void validate(const RenderRequest& request) {
    if (request.width <= 0 || request.height <= 0) throw std::runtime_error("the image size must be positive");
    if (request.spp <= 0) throw std::runtime_error("samples per pixel must be at least 1");
    if (request.bounces < 0) throw std::runtime_error("bounces must be 0 or more");
}

} // namespace

OfflineRenderer::OfflineRenderer(bool requireGpu)
    : state_(std::make_unique<State>(requireGpu)) {}

OfflineRenderer::~OfflineRenderer() = default;

const std::string& OfflineRenderer::glRenderer() const { return state_->context.renderer(); }

RenderOutput OfflineRenderer::render(const Scene& scene, const RenderRequest& request) {
    validate(request);
    const auto setupStart = Clock::now();
    const CameraSetup camera = resolveCamera(scene, request.cameraName, request.width, request.height);
    const GpuScene gpuScene(scene, environmentPath(scene, request));
    PathTracePass pathTrace(state_->programs);
    AccumulatePass accumulate(state_->programs, request.width, request.height);
    TonemapPass tonemap(state_->programs);
    const gl::RenderTarget sample = makeGBuffer(request.width, request.height);
    const gl::RenderTarget display(request.width, request.height, {GL_RGBA8});
    const PathTraceSettings settings{request.seed, request.bounces, request.clamp, request.independentSampler,
                                     request.view, request.aoDistance};
    RenderOutput out;
    out.width = request.width;
    out.height = request.height;
    out.glRenderer = state_->context.renderer();
    out.timings.setupMs = millisecondsSince(setupStart);

    const auto renderStart = Clock::now();
    for (int i = 0; i < request.spp; ++i) {
        pathTrace.render(gpuScene, camera, settings, static_cast<std::uint32_t>(i), sample);
        accumulate.add(sample);
        if (request.progress) {
            glFinish();
            request.progress(i + 1, request.spp);
        }
    }
    glFinish();
    out.timings.renderMs = millisecondsSince(renderStart);
    out.timings.msPerSample = out.timings.renderMs / request.spp;
    tonemap.render(accumulate.mean(), camera.exposure + request.exposure,
                   request.tonemapper.value_or(scene.settings.render.tonemapper), display);
    readOutputs(accumulate.mean(), display, request.spp, out);
    return out;
}

RenderOutput renderOffline(const Scene& scene, const RenderRequest& request) {
    OfflineRenderer renderer(request.requireGpu);
    return renderer.render(scene, request);
}

} // namespace glint::renderer
