#pragma once
// Times samples of one scene on a headless context: the scene is uploaded once, then each sample is a
// FrameRenderer frame of the Accumulate configuration (path trace + running mean), finished on the GPU
// before the clock stops. Wall time and process CPU time (all llvmpipe threads) are both kept: on a
// shared machine the CPU time is the steadier figure. Read-backs are not timed.
#include "renderer/frame_renderer.h"
#include "renderer/gl/headless_context.h"
#include "scene/core/scene.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace glint::bench {

struct SampleTime {
    double wallMs = 0.0;
    double cpuMs = 0.0;
};

class SampleTimer {
public:
    SampleTimer();
    const std::string& glRenderer() const { return context_.renderer(); }

    // Uploads `scene` (timed: the upload and BVH build, wall ms) for width x height renders.
    double load(const Scene& scene, int width, int height, int bounces);

    // Renders `samples` samples from a reset history with `seed`; after sample k (1-based) where
    // `readBack(k)` is true, hands the accumulated radiance (RGBA) to `onImage` untimed. Returns the
    // time of all samples.
    SampleTime render(int samples, std::uint32_t seed, const std::function<bool(int)>& readBack = {},
                      const std::function<void(int, const SampleTime&, const renderer::FrameImages&)>& onImage = {});

private:
    gl::HeadlessContext context_;
    renderer::FrameRenderer frames_;
    renderer::FrameSettings settings_;
};

} // namespace glint::bench
