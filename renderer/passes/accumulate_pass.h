#pragma once
// The exact running mean of path-traced samples in RGBA32F, ping-ponged between two G-buffers.
// Depth and object id are kept from the first sample (a mean of ids or of hit/miss depths means
// nothing); radiance, albedos and normal are averaged. After the G-buffer's targets
// (path_trace_pass.h) one more holds the mean squared radiance.
#include "renderer/gl/fullscreen_triangle.h"
#include "renderer/gl/program_cache.h"
#include "renderer/gl/render_target.h"

namespace glint::renderer {

inline constexpr int radianceSquaredAttachment = 7; // gBufferAttachmentCount

// `stopTexture`: adaptive sampling's stops (adaptive_sampling.h), attached as the depth buffer; 0: none.
gl::RenderTarget makeAccumulationBuffer(int width, int height, GLuint stopTexture = 0);

class AccumulatePass {
public:
    // `stopTexture`: as makeAccumulationBuffer's, for add(sample, true).
    AccumulatePass(gl::ProgramCache& programs, int width, int height, GLuint stopTexture = 0);
    // cullStopped: the pixels adaptive sampling stopped keep their mean and cost nothing (their
    // mean is in both targets: AdaptiveSamplingPass::test copies it into next() as they stop).
    void add(const gl::RenderTarget& sample, bool cullStopped = false);
    void reset() { count_ = 0; }
    // Zeroes both targets, so pixels a scissor keeps out hold no earlier render (render regions).
    void clear() { targets_[0].clear(); targets_[1].clear(); }
    int sampleCount() const { return count_; }
    const gl::RenderTarget& mean() const { return targets_[current_]; }
    const gl::RenderTarget& next() const { return targets_[1 - current_]; } // what the next add() writes

private:
    gl::ProgramCache& programs_;
    gl::FullscreenTriangle triangle_;
    gl::RenderTarget targets_[2];
    int current_ = 0;
    int count_ = 0;
};

} // namespace glint::renderer
