#include "renderer/passes/region_composite.h"

#include <algorithm>

namespace glint::renderer {
namespace {

GLuint framebufferOf(const gl::RenderTarget& target) {
    target.bindForDrawing();
    GLint fbo = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &fbo);
    return static_cast<GLuint>(fbo);
}

// Copies attachment 0 of `from` (all of it, scaled to nearest pixels) or one rectangle of it.
void blit(const gl::RenderTarget& from, const gl::RenderTarget& to, const PixelRect& source, const PixelRect& target) {
    const GLuint read = framebufferOf(from);
    framebufferOf(to); // binds `to` for drawing, attachment 0 as its only draw buffer
    glBindFramebuffer(GL_READ_FRAMEBUFFER, read);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glBlitFramebuffer(source.x, source.y, source.x + source.width, source.y + source.height, target.x, target.y,
                      target.x + target.width, target.y + target.height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

PixelRect whole(const gl::RenderTarget& t) { return {0, 0, t.width(), t.height()}; }

} // namespace

int reconstructionReach(const ConfigurationTraits& traits, int svgfIterations) {
    if (traits.accumulate) return 0;
    constexpr int antiLagReach = 3; // a pixel takes the largest lambda of its 2x2 nearest 3x3 strata
    constexpr int varianceReach = 3;
    // The filtered still mean the converge stage fades into (mean_denoise_pass.h, 5 steps): its
    // taps reach 62 px, its 5x5 spatial variance and each step's 3x3 variance blur further, and the
    // variance it spreads enters every later step's weights. Measured: region edges are bit-equal
    // to the full frame's from 76 px on (test_render_region), not at 75.
    constexpr int meanDenoiseReach = 76;
    int reach = 0;
    if (traits.svgf) reach = 2 * ((1 << std::clamp(svgfIterations, 1, 16)) - 1) + varianceReach + antiLagReach;
    else if (traits.taa) reach = antiLagReach;
    if (traits.taa) reach += 1;
    return std::max(reach, meanDenoiseReach);
}

bool RegionComposite::fits(int width, int height) const {
    return composite_ && composite_->width() == width && composite_->height() == height;
}

void RegionComposite::freeze(const gl::RenderTarget* last, int width, int height) {
    if (last == composite_.get() && fits(width, height)) return; // already the last image
    const gl::RenderTarget* source = last ? last : composite_.get();
    auto next = std::make_unique<gl::RenderTarget>(width, height, std::vector<GLenum>{GL_RGBA32F});
    const bool scissor = glIsEnabled(GL_SCISSOR_TEST);
    glDisable(GL_SCISSOR_TEST); // blits and clears obey the scissor
    if (source) blit(*source, *next, whole(*source), whole(*next));
    else next->clear();
    if (scissor) glEnable(GL_SCISSOR_TEST);
    composite_ = std::move(next);
}

void RegionComposite::update(const gl::RenderTarget& result, const PixelRect& rect) {
    if (composite_ && &result != composite_.get()) blit(result, *composite_, rect, rect);
}

} // namespace glint::renderer
