#pragma once
// Temporal anti-aliasing (shaders/reconstruction/taa.frag.glsl). Inputs: this frame's linear
// radiance, motion vectors, the current and previous G-buffers (disocclusion), anti-lag (stale
// lighting shortens history). Internal: two history targets, swapped each frame. Output: the new history (linear radiance, alpha = history length).
#include "renderer/passes/fullscreen_stage.h"

namespace glint::renderer {

struct TaaSettings {
    float minBlend = 0.1f;  // current frame's weight on a long still history (~10 frames)
    int clipMode = 0;        // 0 variance clip, 1 min/max clamp, 2 none (TaaClip's order)
    float clipGamma = 1.25f; // variance-clipping box half-size in standard deviations
    bool perceptualBlend = false; // blend tonemapped colour (darkens noisy input; taa.frag.glsl)
};

struct TaaInputs {
    const gl::RenderTarget& radiance; // attachment 0
    const gl::RenderTarget& motion;
    const gl::RenderTarget& gbuffer;          // path_trace_pass.h attachments
    const gl::RenderTarget& previousGBuffer;  // attachments 0 normal + depth, 1 id
    bool historyValid = false;
    const gl::RenderTarget& antiLag; // attachment antiLagAttachment, x: how stale history is (anti_lag_pass.h)
};

class TaaPass {
public:
    TaaPass(gl::ProgramCache& programs, int width, int height);
    const gl::RenderTarget& execute(const TaaInputs& in, const TaaSettings& settings = {});

private:
    gl::ProgramCache& programs_;
    gl::FullscreenTriangle triangle_;
    gl::RenderTarget history_[2];
    int current_ = 0;
};

} // namespace glint::renderer
