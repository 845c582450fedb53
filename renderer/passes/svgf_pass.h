#pragma once
// Spatiotemporal variance-guided filtering (Schied et al. 2017), after Falcor's SVGFPass.
// Inputs: this frame's G-buffer (radiance, albedo, normal + depth, id), motion vectors, the
// previous frame's normal + depth and id. Internal: temporal targets (illumination + variance,
// moments + history length) and the filtered history, both swapped per frame; two a-trous
// ping-pong targets. Output: filtered radiance (attachment 0).
// Stages, one shader each: reproject -> estimateVariance -> atrous x iterations -> modulate.
#include "renderer/passes/fullscreen_stage.h"

namespace glint::renderer {

struct SvgfSettings {
    int iterations = 5;
    float alpha = 0.2f;         // minimum weight of the current frame in the temporal mean
    float momentsAlpha = 0.2f;
    float sigmaLuminance = 4.0f;
    float sigmaNormal = 128.0f;
    float sigmaDepth = 1.0f;
    float fireflyRatio = 8.0f;  // a pixel may be this many times brighter than its brightest neighbour
};

struct SvgfInputs {
    const gl::RenderTarget& gbuffer;
    const gl::RenderTarget& motion;
    const gl::RenderTarget& previousGBuffer; // attachments 0 normal + depth, 1 id
    bool historyValid = false;
};

class SvgfPass {
public:
    SvgfPass(gl::ProgramCache& programs, int width, int height);
    const gl::RenderTarget& execute(const SvgfInputs& in, const SvgfSettings& settings = {});

private:
    void reproject(const SvgfInputs& in, const SvgfSettings& settings);
    void estimateVariance(const SvgfInputs& in);
    const gl::RenderTarget& atrous(const SvgfInputs& in, const SvgfSettings& settings);
    void modulate(const SvgfInputs& in, const gl::RenderTarget& filtered);

    gl::ProgramCache& programs_;
    gl::FullscreenTriangle triangle_;
    gl::RenderTarget temporal_[2]; // 0: illumination rgb + variance, 1: moments + history length
    gl::RenderTarget filteredHistory_[2];
    gl::RenderTarget pingPong_[2];
    gl::RenderTarget output_;
    int current_ = 0;
};

} // namespace glint::renderer
