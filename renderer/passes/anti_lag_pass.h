#pragma once
// Anti-lag: where the lighting under a pixel changed (a light moved, dimmed or went off; a moving
// object's shadow; what an object uncovers), history is stale, and SVGF and TAA would keep it for
// many frames. This pass estimates per pixel how stale (lambda: 0 = history right, 1 = discard it)
// from a temporal gradient measured on strata of antiLagStratum^2 pixels, where 1-spp noise
// averages out: each pixel's luminance minus its reprojected history, and a t-test of their mean
// against their spread (shaders/reconstruction/anti_lag_gradient.frag.glsl). SVGF raises its temporal alpha and TAA its
// blend weight to lambda. A still, converging image has no gradient, so it changes nothing there.
// Inputs: the G-buffer, motion vectors, the previous frame's normal + depth and id.
// Internal: per-stratum gradient; luminance moments history, swapped per frame.
// Output: antiLag() attachment antiLagAttachment, x = lambda.
#include "renderer/passes/fullscreen_stage.h"

namespace glint::renderer {

inline constexpr int antiLagAttachment = 1;
inline constexpr int antiLagStratum = 3; // pixels per side of a stratum: noise averages over 9 samples

struct AntiLagSettings {
    bool enabled = true;
    float noiseLow = 3.0f;     // a stratum's change below this many standard errors is noise
    float noiseHigh = 6.0f;    // above this many it is certain
    float fullChange = 0.4f;   // relative change of a stratum's mean that discards history entirely
    int minPixels = 6;         // of a stratum's 9 that must have history for a gradient
    float spikeSigmas = 4.0f;  // samples clamped to mean + this many sigmas before the test (fireflies)
    float momentsAlpha = 0.1f; // minimum weight of the current frame in the anti-lag moments
};

struct AntiLagInputs {
    const gl::RenderTarget& gbuffer;
    const gl::RenderTarget& motion;
    const gl::RenderTarget& previousGBuffer; // attachments 0 normal + depth, 1 id
    bool historyValid = false;
};

class AntiLagPass {
public:
    AntiLagPass(gl::ProgramCache& programs, int width, int height);
    // Returns the target whose attachment antiLagAttachment holds lambda (all 0 when disabled).
    const gl::RenderTarget& execute(const AntiLagInputs& in, const AntiLagSettings& settings = {});
    const gl::RenderTarget& gradient() const { return gradient_; } // per stratum: lambda, sigmas, relative, count

private:
    void measureGradient(const AntiLagInputs& in, const AntiLagSettings& settings);
    void updateHistory(const AntiLagInputs& in, const AntiLagSettings& settings);

    gl::ProgramCache& programs_;
    gl::FullscreenTriangle triangle_;
    gl::RenderTarget gradient_;
    gl::RenderTarget history_[2]; // 0: luminance moments + history length, 1: lambda
    int current_ = 0;
};

} // namespace glint::renderer
