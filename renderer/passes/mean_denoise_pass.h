#pragma once
// An edge-avoiding filter of the accumulated mean (the still view's running mean of every sample):
// demodulated by albedo, a-trous wavelet steps guided by depth, normal and object id, and a
// luminance stop scaled by the variance of the mean, which falls as 1/n as samples arrive. So a
// still view is clean after a few samples, the filter's bias falls with its noise, and the image
// tends to the exact mean. Deterministic (a pure function of the mean and n).
// Input: an AccumulatePass mean (its G-buffer attachments and the mean squared radiance).
// Stages: prepare (demodulate, variance of the mean) -> atrous x iterations -> modulate.
// Output: filtered radiance (attachment 0); targets follow the input's size.
//
// The filter runs whole (execute) or in steps of rows (advance), for a host that must keep each
// frame short on a slow GL: a step runs the next rows of the current stage under a scissor, then
// of the stages after it, so the steps of one filtering give the pixels of execute() exactly.
#include "renderer/passes/fullscreen_stage.h"

#include <algorithm>
#include <memory>

namespace glint::renderer {

struct MeanDenoiseSettings {
    int iterations = 5;
    float sigmaLuminance = 1.5f; // in standard deviations of the mean (docs/DENOISING.md)
    float sigmaNormal = 128.0f;
    float sigmaDepth = 1.0f;
    friend bool operator==(const MeanDenoiseSettings&, const MeanDenoiseSettings&) = default;
};

class MeanDenoisePass {
public:
    explicit MeanDenoisePass(gl::ProgramCache& programs);
    ~MeanDenoisePass();
    // `mean`: an accumulation buffer holding `samples` samples. Filters it whole; a filtering in
    // steps in progress is dropped.
    const gl::RenderTarget& execute(const gl::RenderTarget& mean, int samples, const MeanDenoiseSettings& settings = {});
    // Runs at most `rows` rows of the filtering of `mean` with `samples` (counted over its stages:
    // rows x (iterations + 2) in all), starting it where none of these is in progress; returns the
    // rows run. The caller keeps the mean unchanged while inProgress(): output() changes when it ends.
    int advance(const gl::RenderTarget& mean, int samples, int rows, const MeanDenoiseSettings& settings = {});
    bool inProgress() const { return job_.samples > 0; }
    // Stages of one filtering, each over every row: prepare, the a-trous iterations, modulate.
    static int stageCount(const MeanDenoiseSettings& settings = {}) { return std::max(settings.iterations, 0) + 2; }
    void cancel() { job_ = {}; }
    const gl::RenderTarget& output() const; // the last finished filtering's (valid after one)

private:
    struct Targets;
    struct Job {
        int samples = 0; // 0: none in progress
        MeanDenoiseSettings settings;
        int stage = 0;   // 0: prepare, 1..iterations: a-trous, iterations + 1: modulate
        int nextRow = 0; // the first row of `stage` not yet run
    };
    void drawStage(const gl::RenderTarget& mean, int stage);
    gl::ProgramCache& programs_;
    gl::FullscreenTriangle triangle_;
    std::unique_ptr<Targets> targets_;
    Job job_;
};

} // namespace glint::renderer
