#include "renderer/passes/adaptive_sampling.h"

#include "renderer/passes/accumulate_pass.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace glint::renderer {
namespace {

constexpr float stopDepthScale = 16777216.0f; // 2^24: n / 2^24 is exact in a float for every n in use

gl::Texture makeStopTexture(int width, int height) {
    gl::Texture texture = gl::makeTexture();
    glBindTexture(GL_TEXTURE_2D, texture.get());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, width, height, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glBindTexture(GL_TEXTURE_2D, 0);
    return texture;
}

} // namespace

int adaptiveMinSamples(const AdaptiveSampling& settings, int spp) {
    // Mean's thresholds are far below Even's for the same image (its rule divides by n), so Cycles'
    // formula would hold every tile to hundreds of samples; its estimate needs only a few.
    const auto cyclesMinimum = [&] { return static_cast<int>(std::ceil(16.0 / std::pow(double(settings.threshold), 0.3))); };
    const int automatic = settings.threshold <= 0.0f ? spp : settings.goal == AdaptiveGoal::Mean ? 16 : cyclesMinimum();
    const int wanted = settings.minSamples > 0 ? settings.minSamples : automatic;
    return std::clamp(wanted, std::min(2, spp), std::max(spp, 1));
}

PixelRect alignedToTiles(const PixelRect& rect, int width, int height) {
    const int left = rect.x / adaptiveTile * adaptiveTile;
    const int bottom = rect.y / adaptiveTile * adaptiveTile;
    const int right = std::min((rect.x + rect.width + adaptiveTile - 1) / adaptiveTile * adaptiveTile, width);
    const int top = std::min((rect.y + rect.height + adaptiveTile - 1) / adaptiveTile * adaptiveTile, height);
    return {left, bottom, right - left, top - bottom};
}

bool adaptiveTestDue(int samples, int minSamples) {
    return samples >= std::max(minSamples, 2) && (samples - minSamples) % 4 == 0;
}

AdaptiveSamplingPass::AdaptiveSamplingPass(gl::ProgramCache& programs, int width, int height)
    : programs_(programs), width_(width), height_(height), stops_(makeStopTexture(width, height)),
      fbo_(gl::makeFramebuffer()),
      tiles_((width + adaptiveTile - 1) / adaptiveTile, (height + adaptiveTile - 1) / adaptiveTile, {GL_R32F}),
      query_(gl::makeQuery()) {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.get());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, stops_.get(), 0);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("adaptive sampling's stop target incomplete (status 0x" + std::to_string(status) + ")");
    reset(PixelRect{0, 0, width, height});
}

void AdaptiveSamplingPass::reset(const PixelRect& traced) {
    const SavedDepthState depth = SavedDepthState::current();
    glDepthMask(GL_TRUE); // clears obey the write mask
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.get());
    GLint scissored = 0;
    glGetIntegerv(GL_SCISSOR_TEST, &scissored);
    glDisable(GL_SCISSOR_TEST); // every pixel samples again, inside a region or not
    const GLfloat one = 1.0f;
    glClearBufferfv(GL_DEPTH, 0, &one);
    if (scissored) glEnable(GL_SCISSOR_TEST);
    depth.restore();
    traced_ = traced.width * traced.height;
    stopped_ = 0;
}

void AdaptiveSamplingPass::test(const gl::RenderTarget& mean, const gl::RenderTarget& next, int samples, const AdaptiveSampling& settings) {
    if (samples < 2 || allStopped()) return;
    const SavedDepthState depth = SavedDepthState::current();
    markConvergedTiles(mean, samples, settings);
    static_assert(radianceSquaredAttachment == 7);
    const gl::ShaderProgram& program = programs_.get(
        {"fullscreen.vert.glsl", "passes/adaptive_test.frag.glsl", {}, {"out0", "out1", "out2", "out3", "out4", "out5", "out6", "out7"}});
    program.use();
    const char* inputs[] = {"uMean0", "uMean1", "uMean2", "uMean3", "uMean4", "uMean5", "uMean6", "uMean7"};
    for (int i = 0; i <= radianceSquaredAttachment; ++i) mean.bindTexture(i, static_cast<GLuint>(i), program.uniform(inputs[i]));
    tiles_.bindTexture(0, radianceSquaredAttachment + 1, program.uniform("uTileConverged"));
    glUniform1f(program.uniform("uSampleCount"), static_cast<float>(samples));
    next.bindForDrawing();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    // The fragments that pass are the pixels stopping now; counting them waits for this draw, short
    // next to the sample before it.
    glBeginQuery(GL_SAMPLES_PASSED, query_.get());
    triangle_.draw();
    glEndQuery(GL_SAMPLES_PASSED);
    GLuint stoppedNow = 0;
    glGetQueryObjectuiv(query_.get(), GL_QUERY_RESULT, &stoppedNow);
    stopped_ += static_cast<int>(stoppedNow);
    depth.restore();
}

// The first stage: tiles_ holds 1 where a tile has converged by the goal's rule. Every tile is
// tested (the caller's scissor counts full-size pixels, not tiles); the second stage reads the
// traced ones.
void AdaptiveSamplingPass::markConvergedTiles(const gl::RenderTarget& mean, int samples, const AdaptiveSampling& settings) {
    gl::Defines defines;
    if (settings.goal == AdaptiveGoal::Mean) defines["GOAL_MEAN"] = "";
    const gl::ShaderProgram& program = programs_.get({"fullscreen.vert.glsl", "passes/adaptive_tiles.frag.glsl", defines, {"outTile"}});
    program.use();
    mean.bindTexture(0, 0, program.uniform("uMeanRadiance"));
    mean.bindTexture(radianceSquaredAttachment, 1, program.uniform("uMeanRadianceSquared"));
    glUniform1f(program.uniform("uSampleCount"), static_cast<float>(samples));
    glUniform1f(program.uniform("uThreshold"), settings.threshold);
    glUniform2i(program.uniform("uImageSize"), width_, height_);
    bindStopTexture(stops_.get(), 2, program);
    const GLboolean scissored = glIsEnabled(GL_SCISSOR_TEST);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_DEPTH_TEST);
    tiles_.bindForDrawing();
    triangle_.draw();
    if (scissored) glEnable(GL_SCISSOR_TEST);
}

std::vector<float> AdaptiveSamplingPass::sampleCounts(int samples) const {
    std::vector<float> counts(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.get());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width_, height_, GL_DEPTH_COMPONENT, GL_FLOAT, counts.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    for (float& c : counts) c = c < 1.0f ? std::round(c * stopDepthScale) : static_cast<float>(samples);
    return counts;
}

void bindStopTexture(GLuint stopTexture, GLuint unit, const gl::ShaderProgram& program) {
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D, stopTexture);
    glUniform1i(program.uniform("uStopDepth"), static_cast<GLint>(unit));
}

SavedDepthState SavedDepthState::current() {
    SavedDepthState s;
    s.test = glIsEnabled(GL_DEPTH_TEST);
    glGetBooleanv(GL_DEPTH_WRITEMASK, &s.mask);
    glGetIntegerv(GL_DEPTH_FUNC, &s.func);
    return s;
}

void SavedDepthState::restore() const {
    if (test) glEnable(GL_DEPTH_TEST);
    else glDisable(GL_DEPTH_TEST);
    glDepthMask(mask);
    glDepthFunc(static_cast<GLenum>(func));
}

CullStoppedPixels::CullStoppedPixels(bool active) {
    if (!active) return;
    saved_ = SavedDepthState::current();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS); // the triangle's 0.5 passes where the stop depth is 1 (still sampling)
    glDepthMask(GL_FALSE);
}

CullStoppedPixels::~CullStoppedPixels() {
    if (saved_) saved_->restore();
}

} // namespace glint::renderer
