#pragma once
// Spatiotemporal variance-guided filtering (Schied et al. 2017), after Falcor's SVGFPass, with the
// diffuse and specular lobes apart: each is demodulated by its own albedo and keeps its own history,
// moments and variance; the specular lobe's a-trous filter shrinks and its edge stops tighten with
// the surface's roughness, so a sharp reflection on a rough base is not blurred with the diffuse light.
// Inputs: this frame's G-buffer (radiance and its specular part, albedos, normal + depth, id,
// roughness), motion vectors, the previous frame's normal + depth and id.
// Internal, each with a diffuse and a specular attachment: temporal targets (illumination + variance;
// plus moments and history length) and the filtered history, both swapped per frame; two a-trous
// ping-pong targets. Output: filtered radiance, the lobes re-modulated and summed (attachment 0).
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
    // The specular lobe gets all iterations from this roughness up; smoother surfaces get fewer
    // (one at roughness 0) and stricter luminance and normal stops.
    float specularFullRoughness = 0.5f;
};

struct SvgfInputs {
    const gl::RenderTarget& gbuffer;
    const gl::RenderTarget& motion;
    const gl::RenderTarget& previousGBuffer; // attachments 0 normal + depth, 1 id
    bool historyValid = false;
    const gl::RenderTarget& antiLag; // attachment antiLagAttachment, x: how stale history is (anti_lag_pass.h)
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
    // 0: diffuse illumination rgb + variance, 1: the same for the specular lobe,
    // 2: luminance moments (diffuse E[l], E[l^2], specular E[l], E[l^2]), 3: x = history length.
    gl::RenderTarget temporal_[2];
    gl::RenderTarget filteredHistory_[2]; // 0: diffuse, 1: specular (the lobes' attachments below too)
    gl::RenderTarget pingPong_[2];
    gl::RenderTarget output_;
    int current_ = 0;
};

} // namespace glint::renderer
