#include "renderer/passes/mean_denoise_pass.h"

#include "renderer/passes/accumulate_pass.h"
#include "renderer/passes/path_trace_pass.h"

#include <algorithm>

namespace glint::renderer {

struct MeanDenoisePass::Targets {
    Targets(int width, int height)
        : pingPong{gl::RenderTarget(width, height, {GL_RGBA32F}), gl::RenderTarget(width, height, {GL_RGBA32F})},
          output(width, height, {GL_RGBA32F}) {}
    gl::RenderTarget pingPong[2]; // illumination rgb + variance of the mean
    gl::RenderTarget output;
};

MeanDenoisePass::MeanDenoisePass(gl::ProgramCache& programs) : programs_(programs) {}
MeanDenoisePass::~MeanDenoisePass() = default;

const gl::RenderTarget& MeanDenoisePass::output() const { return targets_->output; }

const gl::RenderTarget& MeanDenoisePass::execute(const gl::RenderTarget& mean, int samples, const MeanDenoiseSettings& settings) {
    if (!targets_ || targets_->output.width() != mean.width() || targets_->output.height() != mean.height())
        targets_ = std::make_unique<Targets>(mean.width(), mean.height());
    Targets& t = *targets_;
    runStage(programs_, triangle_,
             {"reconstruction/mean_denoise_prepare.frag.glsl",
              {"outIllumination"},
              {{"uRadiance", mean, radianceAttachment},
               {"uRadianceSquared", mean, radianceSquaredAttachment},
               {"uDiffuseAlbedo", mean, diffuseAlbedoAttachment},
               {"uSpecularAlbedo", mean, specularAlbedoAttachment},
               {"uNormalDepth", mean, normalDepthAttachment},
               {"uObjectId", mean, objectIdAttachment}},
              [&](const gl::ShaderProgram& p) { glUniform1f(p.uniform("uSamples"), static_cast<float>(samples)); }},
             t.pingPong[0]);
    const int iterations = std::max(settings.iterations, 0);
    for (int i = 0; i < iterations; ++i) {
        runStage(programs_, triangle_,
                 {"reconstruction/mean_denoise_atrous.frag.glsl",
                  {"outIllumination"},
                  {{"uIllumination", t.pingPong[i % 2], 0},
                   {"uNormalDepth", mean, normalDepthAttachment},
                   {"uObjectId", mean, objectIdAttachment}},
                  [&](const gl::ShaderProgram& p) {
                      glUniform1i(p.uniform("uStep"), 1 << i);
                      glUniform1f(p.uniform("uSigmaLuminance"), settings.sigmaLuminance);
                      glUniform1f(p.uniform("uSigmaNormal"), settings.sigmaNormal);
                      glUniform1f(p.uniform("uSigmaDepth"), settings.sigmaDepth);
                  }},
                 t.pingPong[(i + 1) % 2]);
    }
    runStage(programs_, triangle_,
             {"reconstruction/mean_denoise_modulate.frag.glsl",
              {"outRadiance"},
              {{"uIllumination", t.pingPong[iterations % 2], 0},
               {"uRadiance", mean, radianceAttachment},
               {"uDiffuseAlbedo", mean, diffuseAlbedoAttachment},
               {"uSpecularAlbedo", mean, specularAlbedoAttachment},
               {"uNormalDepth", mean, normalDepthAttachment}},
              {}},
             t.output);
    return t.output;
}

} // namespace glint::renderer
