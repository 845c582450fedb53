#include "renderer/passes/svgf_pass.h"

#include "renderer/passes/anti_lag_pass.h"
#include "renderer/passes/path_trace_pass.h"

#include <algorithm>

namespace glint::renderer {
namespace {

gl::RenderTarget rgba(int width, int height, int attachments = 1) {
    return gl::RenderTarget(width, height, std::vector<GLenum>(static_cast<std::size_t>(attachments), GL_RGBA32F));
}

constexpr int diffuseLobe = 0;
constexpr int specularLobe = 1;
constexpr int momentsAttachment = 2;
constexpr int historyLengthAttachment = 3;

} // namespace

SvgfPass::SvgfPass(gl::ProgramCache& programs, int width, int height)
    : programs_(programs), temporal_{rgba(width, height, 4), rgba(width, height, 4)},
      filteredHistory_{rgba(width, height, 2), rgba(width, height, 2)},
      pingPong_{rgba(width, height, 2), rgba(width, height, 2)}, output_(rgba(width, height)) {}

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
              {"outDiffuse", "outSpecular", "outMoments", "outHistoryLength"},
              {{"uRadiance", in.gbuffer, radianceAttachment},
               {"uSpecularRadiance", in.gbuffer, specularRadianceAttachment},
               {"uDiffuseAlbedo", in.gbuffer, diffuseAlbedoAttachment},
               {"uSpecularAlbedo", in.gbuffer, specularAlbedoAttachment},
               {"uNormalDepth", in.gbuffer, normalDepthAttachment},
               {"uObjectId", in.gbuffer, objectIdAttachment},
               {"uMotion", in.motion, 0},
               {"uPreviousNormalDepth", in.previousGBuffer, 0},
               {"uPreviousObjectId", in.previousGBuffer, 1},
               {"uHistoryDiffuse", filteredHistory_[previous], diffuseLobe},
               {"uHistorySpecular", filteredHistory_[previous], specularLobe},
               {"uHistoryMoments", temporal_[previous], momentsAttachment},
               {"uHistoryLength", temporal_[previous], historyLengthAttachment},
               {"uAntiLag", in.antiLag, antiLagAttachment}},
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
              {"outDiffuse", "outSpecular"},
              {{"uDiffuse", temporal_[current_], diffuseLobe},
               {"uSpecular", temporal_[current_], specularLobe},
               {"uMoments", temporal_[current_], momentsAttachment},
               {"uHistoryLength", temporal_[current_], historyLengthAttachment},
               {"uNormalDepth", in.gbuffer, normalDepthAttachment},
               {"uObjectId", in.gbuffer, objectIdAttachment}},
              {}},
             pingPong_[0]);
}

// Iteration 0 writes the next frame's history (the paper's choice: history is lightly filtered).
const gl::RenderTarget& SvgfPass::atrous(const SvgfInputs& in, const SvgfSettings& settings) {
    const gl::RenderTarget* source = &pingPong_[0];
    const int iterations = std::max(settings.iterations, 1);
    for (int i = 0; i < iterations; ++i) {
        const gl::RenderTarget& destination = i == 0 ? filteredHistory_[current_] : pingPong_[i % 2];
        runStage(programs_, triangle_,
                 {"reconstruction/svgf_atrous.frag.glsl",
                  {"outDiffuse", "outSpecular"},
                  {{"uDiffuse", *source, diffuseLobe},
                   {"uSpecular", *source, specularLobe},
                   {"uNormalDepth", in.gbuffer, normalDepthAttachment},
                   {"uObjectId", in.gbuffer, objectIdAttachment},
                   {"uSpecularAlbedo", in.gbuffer, specularAlbedoAttachment},
                   {"uHistoryLength", temporal_[current_], historyLengthAttachment},
                   {"uAntiLag", in.antiLag, antiLagAttachment}},
                  [&](const gl::ShaderProgram& p) {
                      glUniform1i(p.uniform("uStep"), 1 << i);
                      glUniform1i(p.uniform("uIteration"), i);
                      glUniform1i(p.uniform("uIterations"), iterations);
                      glUniform1i(p.uniform("uHistoryValid"), in.historyValid ? 1 : 0);
                      glUniform1f(p.uniform("uSigmaLuminance"), settings.sigmaLuminance);
                      glUniform1f(p.uniform("uSigmaNormal"), settings.sigmaNormal);
                      glUniform1f(p.uniform("uSigmaDepth"), settings.sigmaDepth);
                      glUniform1f(p.uniform("uSpecularFullRoughness"), settings.specularFullRoughness);
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
              {{"uDiffuse", filtered, diffuseLobe},
               {"uSpecular", filtered, specularLobe},
               {"uDiffuseAlbedo", in.gbuffer, diffuseAlbedoAttachment},
               {"uSpecularAlbedo", in.gbuffer, specularAlbedoAttachment}},
              {}},
             output_);
}

} // namespace glint::renderer
