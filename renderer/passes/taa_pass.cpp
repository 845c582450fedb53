#include "renderer/passes/taa_pass.h"

#include "renderer/passes/anti_lag_pass.h"
#include "renderer/passes/path_trace_pass.h"

namespace glint::renderer {

TaaPass::TaaPass(gl::ProgramCache& programs, int width, int height)
    : programs_(programs), history_{gl::RenderTarget(width, height, {GL_RGBA32F}), gl::RenderTarget(width, height, {GL_RGBA32F})} {}

const gl::RenderTarget& TaaPass::execute(const TaaInputs& in, const TaaSettings& settings) {
    const int next = 1 - current_;
    runStage(programs_, triangle_,
             {"reconstruction/taa.frag.glsl",
              {"outColor"},
              {{"uCurrent", in.radiance, 0},
               {"uHistory", history_[current_], 0},
               {"uMotion", in.motion, 0},
               {"uNormalDepth", in.gbuffer, normalDepthAttachment},
               {"uObjectId", in.gbuffer, objectIdAttachment},
               {"uPreviousNormalDepth", in.previousGBuffer, 0},
               {"uPreviousObjectId", in.previousGBuffer, 1},
               {"uAntiLag", in.antiLag, antiLagAttachment}},
              [&](const gl::ShaderProgram& p) {
                  glUniform1i(p.uniform("uHistoryValid"), in.historyValid ? 1 : 0);
                  glUniform1f(p.uniform("uMinBlend"), settings.minBlend);
                  glUniform1i(p.uniform("uClipMode"), settings.clipMode);
                  glUniform1f(p.uniform("uClipGamma"), settings.clipGamma);
                  glUniform1i(p.uniform("uPerceptualBlend"), settings.perceptualBlend ? 1 : 0);
              }},
             history_[next]);
    current_ = next;
    return history_[current_];
}

} // namespace glint::renderer
