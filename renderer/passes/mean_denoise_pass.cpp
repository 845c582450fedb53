#include "renderer/passes/mean_denoise_pass.h"

#include "renderer/gl/scissor_guard.h"
#include "renderer/passes/accumulate_pass.h"
#include "renderer/passes/path_trace_pass.h"

#include <algorithm>
#include <limits>

namespace glint::renderer {

struct MeanDenoisePass::Targets {
    Targets(int width, int height)
        : pingPong{gl::RenderTarget(width, height, {GL_RGBA32F}), gl::RenderTarget(width, height, {GL_RGBA32F})},
          output{gl::RenderTarget(width, height, {GL_RGBA32F}), gl::RenderTarget(width, height, {GL_RGBA32F})} {}
    gl::RenderTarget pingPong[2]; // illumination rgb + variance of the mean
    gl::RenderTarget output[2];   // the finished filtering, and the one a filtering in steps writes
    int finished = 0;             // which output holds the finished one
};

MeanDenoisePass::MeanDenoisePass(gl::ProgramCache& programs) : programs_(programs) {}
MeanDenoisePass::~MeanDenoisePass() = default;

const gl::RenderTarget& MeanDenoisePass::output() const { return targets_->output[targets_->finished]; }

const gl::RenderTarget& MeanDenoisePass::execute(const gl::RenderTarget& mean, int samples, const MeanDenoiseSettings& settings) {
    cancel();
    advance(mean, samples, std::numeric_limits<int>::max(), settings);
    return output();
}

int MeanDenoisePass::advance(const gl::RenderTarget& mean, int samples, int rows, const MeanDenoiseSettings& settings) {
    if (!targets_ || targets_->output[0].width() != mean.width() || targets_->output[0].height() != mean.height()) {
        targets_ = std::make_unique<Targets>(mean.width(), mean.height());
        cancel();
    }
    if (job_.samples != samples || !(job_.settings == settings)) job_ = {samples, settings, 0, 0};
    const int height = mean.height();
    const int lastStage = stageCount(settings) - 1;
    const gl::ScissorGuard guard;
    glEnable(GL_SCISSOR_TEST);
    int run = 0;
    while (run < rows && job_.samples > 0) {
        const int band = std::min(rows - run, height - job_.nextRow);
        glScissor(0, job_.nextRow, mean.width(), band);
        drawStage(mean, job_.stage);
        run += band;
        job_.nextRow += band;
        if (job_.nextRow < height) continue;
        job_.nextRow = 0;
        if (++job_.stage <= lastStage) continue;
        targets_->finished = 1 - targets_->finished;
        cancel();
    }
    return run;
}

void MeanDenoisePass::drawStage(const gl::RenderTarget& mean, int stage) {
    Targets& t = *targets_;
    const MeanDenoiseSettings& s = job_.settings;
    const int iterations = std::max(s.iterations, 0);
    if (stage == 0) {
        runStage(programs_, triangle_,
                 {"reconstruction/mean_denoise_prepare.frag.glsl",
                  {"outIllumination"},
                  {{"uRadiance", mean, radianceAttachment},
                   {"uRadianceSquared", mean, radianceSquaredAttachment},
                   {"uDiffuseAlbedo", mean, diffuseAlbedoAttachment},
                   {"uSpecularAlbedo", mean, specularAlbedoAttachment},
                   {"uNormalDepth", mean, normalDepthAttachment},
                   {"uObjectId", mean, objectIdAttachment}},
                  [&](const gl::ShaderProgram& p) { glUniform1f(p.uniform("uSamples"), static_cast<float>(job_.samples)); }},
                 t.pingPong[0]);
    } else if (stage <= iterations) {
        const int i = stage - 1;
        runStage(programs_, triangle_,
                 {"reconstruction/mean_denoise_atrous.frag.glsl",
                  {"outIllumination"},
                  {{"uIllumination", t.pingPong[i % 2], 0},
                   {"uNormalDepth", mean, normalDepthAttachment},
                   {"uObjectId", mean, objectIdAttachment}},
                  [&](const gl::ShaderProgram& p) {
                      glUniform1i(p.uniform("uStep"), 1 << i);
                      glUniform1f(p.uniform("uSigmaLuminance"), s.sigmaLuminance);
                      glUniform1f(p.uniform("uSigmaNormal"), s.sigmaNormal);
                      glUniform1f(p.uniform("uSigmaDepth"), s.sigmaDepth);
                  }},
                 t.pingPong[(i + 1) % 2]);
    } else {
        runStage(programs_, triangle_,
                 {"reconstruction/mean_denoise_modulate.frag.glsl",
                  {"outRadiance"},
                  {{"uIllumination", t.pingPong[iterations % 2], 0},
                   {"uRadiance", mean, radianceAttachment},
                   {"uDiffuseAlbedo", mean, diffuseAlbedoAttachment},
                   {"uSpecularAlbedo", mean, specularAlbedoAttachment},
                   {"uNormalDepth", mean, normalDepthAttachment}},
                  {}},
                 t.output[1 - t.finished]);
    }
}

} // namespace glint::renderer
