#pragma once
// An edge-avoiding filter of the accumulated mean (the still view's running mean of every sample):
// demodulated by albedo, a-trous wavelet steps guided by depth, normal and object id, and a
// luminance stop scaled by the variance of the mean, which falls as 1/n as samples arrive. So a
// still view is clean after a few samples, the filter's bias falls with its noise, and the image
// tends to the exact mean. Deterministic (a pure function of the mean and n).
// Input: an AccumulatePass mean (its G-buffer attachments and the mean squared radiance).
// Stages: prepare (demodulate, variance of the mean) -> atrous x iterations -> modulate.
// Output: filtered radiance (attachment 0); targets follow the input's size.
#include "renderer/passes/fullscreen_stage.h"

#include <memory>

namespace glint::renderer {

struct MeanDenoiseSettings {
    int iterations = 5;
    float sigmaLuminance = 1.5f; // in standard deviations of the mean (docs/DENOISING.md)
    float sigmaNormal = 128.0f;
    float sigmaDepth = 1.0f;
};

class MeanDenoisePass {
public:
    explicit MeanDenoisePass(gl::ProgramCache& programs);
    ~MeanDenoisePass();
    // `mean`: an accumulation buffer holding `samples` samples.
    const gl::RenderTarget& execute(const gl::RenderTarget& mean, int samples, const MeanDenoiseSettings& settings = {});
    const gl::RenderTarget& output() const; // the last execute()'s (valid after one)

private:
    struct Targets;
    gl::ProgramCache& programs_;
    gl::FullscreenTriangle triangle_;
    std::unique_ptr<Targets> targets_;
};

} // namespace glint::renderer
