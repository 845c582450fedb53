#pragma once
// The running mean of the EXR's render passes (PathTraceSettings::renderPasses): the RENDER_PASSES
// path tracer's targets 3-7 averaged into five RGBA32F targets (ping-pong), by the beauty's formula
// and with the beauty's sample count, so that the passes sum to the beauty up to float rounding.
// Layout of mean() (shaders/pathtrace/render_passes.glsl says what each pass holds):
//   0: yzw Env            1: rgb DiffDir, a Emit.r   2: rgb DiffInd, a Emit.g
//   3: rgb GlossDir, a Emit.b                         4: rgb GlossInd
#include "renderer/gl/fullscreen_triangle.h"
#include "renderer/gl/program_cache.h"
#include "renderer/gl/render_target.h"

namespace glint::renderer {

inline constexpr int renderPassesMeanTargets = 5;

class RenderPassesMean {
public:
    RenderPassesMean(gl::ProgramCache& programs, int width, int height);
    // `sample`: a makeRenderPassesGBuffer target; `count`: the beauty's sample count, this one
    // included; `stopTexture`: as AccumulatePass::add's.
    void add(const gl::RenderTarget& sample, int count, GLuint stopTexture = 0);
    const gl::RenderTarget& mean() const { return targets_[current_]; }

private:
    gl::ProgramCache& programs_;
    gl::FullscreenTriangle triangle_;
    gl::RenderTarget targets_[2];
    int current_ = 0;
};

} // namespace glint::renderer
