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

gl::RenderTarget makeAccumulationBuffer(int width, int height);

class AccumulatePass {
public:
    AccumulatePass(gl::ProgramCache& programs, int width, int height);
    void add(const gl::RenderTarget& sample);
    void reset() { count_ = 0; }
    // Zeroes both targets, so pixels a scissor keeps out hold no earlier render (render regions).
    void clear() { targets_[0].clear(); targets_[1].clear(); }
    int sampleCount() const { return count_; }
    const gl::RenderTarget& mean() const { return targets_[current_]; }

private:
    gl::ProgramCache& programs_;
    gl::FullscreenTriangle triangle_;
    gl::RenderTarget targets_[2];
    int current_ = 0;
    int count_ = 0;
};

} // namespace glint::renderer
