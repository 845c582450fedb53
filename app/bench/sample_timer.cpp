#include "sample_timer.h"

#include "renderer/gpu_scene/camera_setup.h"
#include "renderer/offline_render.h"

#include <epoxy/gl.h>

#include <chrono>
#include <ctime>

namespace glint::bench {
namespace {

using Clock = std::chrono::steady_clock;

double cpuNowMs() { return 1000.0 * static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

} // namespace

SampleTimer::SampleTimer() = default;

double SampleTimer::load(const Scene& scene, int width, int height, int bounces) {
    renderer::RenderRequest request;
    request.configuration = renderer::Configuration::Accumulate;
    request.width = width;
    request.height = height;
    request.bounces = bounces;
    settings_ = renderer::frameSettingsFor(request, 1);
    const auto start = Clock::now();
    frames_.setSettings(settings_);
    frames_.setCamera(renderer::resolveCamera(scene, "", width, height));
    frames_.setScene(scene, renderer::environmentPath(scene, request));
    frames_.resetHistory();
    glFinish();
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

SampleTime SampleTimer::render(int samples, std::uint32_t seed, const std::function<bool(int)>& readBack,
                               const std::function<void(int, const SampleTime&, const renderer::FrameImages&)>& onImage) {
    settings_.seed = seed;
    frames_.setSettings(settings_);
    frames_.resetHistory();
    SampleTime total;
    for (int k = 1; k <= samples; ++k) {
        const auto wall = Clock::now();
        const double cpu = cpuNowMs();
        frames_.renderFrame();
        glFinish();
        total.wallMs += std::chrono::duration<double, std::milli>(Clock::now() - wall).count();
        total.cpuMs += cpuNowMs() - cpu;
        if (readBack && onImage && readBack(k)) onImage(k, total, frames_.readImages());
    }
    return total;
}

} // namespace glint::bench
