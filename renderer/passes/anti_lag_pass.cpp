#include "renderer/passes/anti_lag_pass.h"

#include "renderer/passes/path_trace_pass.h"

namespace glint::renderer {
namespace {

int strata(int pixels) { return (pixels + antiLagStratum - 1) / antiLagStratum; }

// What both stages read: this frame's luminance and surface, its motion, the previous frame's
// surface and the anti-lag history (the same reprojection in both); the history update also reads
// the gradient.
std::vector<StageInput> historyInputs(const AntiLagInputs& in, const gl::RenderTarget& history,
                                      const gl::RenderTarget* gradient = nullptr) {
    std::vector<StageInput> inputs{{"uRadiance", in.gbuffer, radianceAttachment},
                                   {"uDiffuseAlbedo", in.gbuffer, diffuseAlbedoAttachment},
                                   {"uSpecularAlbedo", in.gbuffer, specularAlbedoAttachment},
                                   {"uNormalDepth", in.gbuffer, normalDepthAttachment},
                                   {"uObjectId", in.gbuffer, objectIdAttachment},
                                   {"uMotion", in.motion, 0},
                                   {"uPreviousNormalDepth", in.previousGBuffer, 0},
                                   {"uPreviousObjectId", in.previousGBuffer, 1},
                                   {"uHistory", history, 0}};
    if (gradient) inputs.push_back({"uGradient", *gradient, 0});
    return inputs;
}

} // namespace

AntiLagPass::AntiLagPass(gl::ProgramCache& programs, int width, int height)
    : programs_(programs), gradient_(strata(width), strata(height), {GL_RGBA32F}),
      history_{gl::RenderTarget(width, height, {GL_RGBA32F, GL_RGBA32F}),
               gl::RenderTarget(width, height, {GL_RGBA32F, GL_RGBA32F})} {}

const gl::RenderTarget& AntiLagPass::execute(const AntiLagInputs& in, const AntiLagSettings& settings) {
    current_ = 1 - current_; // this frame writes what the last one did not
    if (!settings.enabled) {
        history_[current_].clear();
        return history_[current_];
    }
    measureGradient(in, settings);
    updateHistory(in, settings);
    return history_[current_];
}

void AntiLagPass::measureGradient(const AntiLagInputs& in, const AntiLagSettings& settings) {
    const gl::RenderTarget& previous = history_[1 - current_];
    runStage(programs_, triangle_,
             {"reconstruction/anti_lag_gradient.frag.glsl",
              {"outGradient"},
              historyInputs(in, previous),
              [&](const gl::ShaderProgram& p) {
                  glUniform1i(p.uniform("uHistoryValid"), in.historyValid ? 1 : 0);
                  glUniform1i(p.uniform("uStratum"), antiLagStratum);
                  glUniform1f(p.uniform("uNoiseLow"), settings.noiseLow);
                  glUniform1f(p.uniform("uNoiseHigh"), settings.noiseHigh);
                  glUniform1f(p.uniform("uFullChange"), settings.fullChange);
                  glUniform1f(p.uniform("uMinPixels"), static_cast<float>(settings.minPixels));
                  glUniform1f(p.uniform("uSpikeSigmas"), settings.spikeSigmas);
              }},
             gradient_);
}

void AntiLagPass::updateHistory(const AntiLagInputs& in, const AntiLagSettings& settings) {
    const gl::RenderTarget& previous = history_[1 - current_];
    runStage(programs_, triangle_,
             {"reconstruction/anti_lag_history.frag.glsl",
              {"outMoments", "outAntiLag"},
              historyInputs(in, previous, &gradient_),
              [&](const gl::ShaderProgram& p) {
                  glUniform1i(p.uniform("uHistoryValid"), in.historyValid ? 1 : 0);
                  glUniform1i(p.uniform("uStratum"), antiLagStratum);
                  glUniform1f(p.uniform("uAlpha"), settings.momentsAlpha);
                  glUniform1f(p.uniform("uSpikeSigmas"), settings.spikeSigmas);
              }},
             history_[current_]);
}

} // namespace glint::renderer
