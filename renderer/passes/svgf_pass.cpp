#include "renderer/passes/svgf_pass.h"

#include "renderer/passes/path_trace_pass.h"

#include <algorithm>

namespace glint::renderer {
namespace {

gl::RenderTarget rgba(int width, int height, int attachments = 1) {
    return gl::RenderTarget(width, height, std::vector<GLenum>(static_cast<std::size_t>(attachments), GL_RGBA32F));
}

} // namespace

SvgfPass::SvgfPass(gl::ProgramCache& programs, int width, int height)
    : programs_(programs), temporal_{rgba(width, height, 2), rgba(width, height, 2)},
      filteredHistory_{rgba(width, height), rgba(width, height)}, pingPong_{rgba(width, height), rgba(width, height)},
      output_(rgba(width, height)) {}

const gl::RenderTarget& SvgfPass::execute(const SvgfInputs& in, const SvgfSettings& settings) {
    current_ = 1 - current_; // swap histories: this frame writes what the last one did not
    reproject(in, settings);
    estimateVariance(in);
    modulate(in, atrous(in, settings));
    return output_;
}

void SvgfPass::reproject(const SvgfInputs& in, const SvgfSettings& settings) {
    const int previous = 1 - current_;
    runStage(programs_, triangle_,
             {"reconstruction/svgf_reproject.frag.glsl",
              {"outIllumination", "outMoments"},
              {{"uRadiance", in.gbuffer, radianceAttachment},
               {"uDiffuseAlbedo", in.gbuffer, diffuseAlbedoAttachment},
               {"uSpecularAlbedo", in.gbuffer, specularAlbedoAttachment},
               {"uNormalDepth", in.gbuffer, normalDepthAttachment},
               {"uObjectId", in.gbuffer, objectIdAttachment},
               {"uMotion", in.motion, 0},
               {"uPreviousNormalDepth", in.previousGBuffer, 0},
               {"uPreviousObjectId", in.previousGBuffer, 1},
               {"uHistoryIllumination", filteredHistory_[previous], 0},
               {"uHistoryMoments", temporal_[previous], 1}},
              [&](const gl::ShaderProgram& p) {
                  glUniform1i(p.uniform("uHistoryValid"), in.historyValid ? 1 : 0);
                  glUniform1f(p.uniform("uAlpha"), settings.alpha);
                  glUniform1f(p.uniform("uMomentsAlpha"), settings.momentsAlpha);
                  glUniform1f(p.uniform("uFireflyRatio"), settings.fireflyRatio);
              }},
             temporal_[current_]);
}

void SvgfPass::estimateVariance(const SvgfInputs& in) {
    runStage(programs_, triangle_,
             {"reconstruction/svgf_variance.frag.glsl",
              {"outIllumination"},
              {{"uIllumination", temporal_[current_], 0},
               {"uMoments", temporal_[current_], 1},
               {"uNormalDepth", in.gbuffer, normalDepthAttachment},
               {"uObjectId", in.gbuffer, objectIdAttachment}},
              {}},
             pingPong_[0]);
}

// Iteration 0 writes the next frame's history (the paper's choice: history is lightly filtered).
const gl::RenderTarget& SvgfPass::atrous(const SvgfInputs& in, const SvgfSettings& settings) {
    const gl::RenderTarget* source = &pingPong_[0];
    for (int i = 0; i < std::max(settings.iterations, 1); ++i) {
        const gl::RenderTarget& destination = i == 0 ? filteredHistory_[current_] : pingPong_[i % 2];
        runStage(programs_, triangle_,
                 {"reconstruction/svgf_atrous.frag.glsl",
                  {"outIllumination"},
                  {{"uIllumination", *source, 0},
                   {"uNormalDepth", in.gbuffer, normalDepthAttachment},
                   {"uObjectId", in.gbuffer, objectIdAttachment}},
                  [&](const gl::ShaderProgram& p) {
                      glUniform1i(p.uniform("uStep"), 1 << i);
                      glUniform1f(p.uniform("uSigmaLuminance"), settings.sigmaLuminance);
                      glUniform1f(p.uniform("uSigmaNormal"), settings.sigmaNormal);
                      glUniform1f(p.uniform("uSigmaDepth"), settings.sigmaDepth);
                  }},
                 destination);
        source = &destination;
    }
    return *source;
}

void SvgfPass::modulate(const SvgfInputs& in, const gl::RenderTarget& filtered) {
    runStage(programs_, triangle_,
             {"reconstruction/svgf_modulate.frag.glsl",
              {"outRadiance"},
              {{"uIllumination", filtered, 0},
               {"uDiffuseAlbedo", in.gbuffer, diffuseAlbedoAttachment},
               {"uSpecularAlbedo", in.gbuffer, specularAlbedoAttachment}},
              {}},
             output_);
}

} // namespace glint::renderer
