#include "renderer/passes/reconstruction.h"

#include "renderer/passes/path_trace_pass.h"

namespace glint::renderer {

Reconstruction::Reconstruction(gl::ProgramCache& programs, int width, int height)
    : programs_(programs), motion_(programs, width, height), antiLag_(programs, width, height),
      svgfPass_(programs, width, height), taaPass_(programs, width, height),
      previousGBuffer_(width, height, {GL_RGBA32F, GL_RGBA32F}), output_(width, height, {GL_RGBA32F}) {}

const gl::RenderTarget& Reconstruction::run(const ReconstructionInputs& in) {
    const gl::RenderTarget& motion = motion_.execute(in.frame, in.camera, in.previousCamera, in.movedInstances);
    const gl::RenderTarget& antiLag = antiLag_.execute({in.frame, motion, previousGBuffer_, in.historyValid}, antiLagSettings);
    const gl::RenderTarget* radiance = &in.frame; // attachment 0 either way
    if (in.traits.svgf) radiance = &svgfPass_.execute({in.frame, motion, previousGBuffer_, in.historyValid, antiLag}, svgf);
    if (in.traits.taa) radiance = &taaPass_.execute({*radiance, motion, in.frame, previousGBuffer_, in.historyValid, antiLag}, taa);
    runStage(programs_, triangle_,
             {"reconstruction/converge.frag.glsl",
              {"outRadiance"},
              {{"uReconstructed", *radiance, 0}, {"uStillMean", in.stillMean, 0}},
              [&](const gl::ShaderProgram& p) {
                  glUniform1f(p.uniform("uStillSamples"), static_cast<float>(in.stillSamples));
                  glUniform1f(p.uniform("uFadeSamples"), static_cast<float>(convergeFadeSamples));
              }},
             output_);
    runStage(programs_, triangle_,
             {"reconstruction/copy_gbuffer.frag.glsl",
              {"outNormalDepth", "outObjectId"},
              {{"uNormalDepth", in.frame, normalDepthAttachment}, {"uObjectId", in.frame, objectIdAttachment}},
              {}},
             previousGBuffer_);
    return output_;
}

} // namespace glint::renderer
