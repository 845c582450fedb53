#include "renderer/passes/region_composite.h"

namespace glint::renderer {
namespace {

GLuint framebufferOf(const gl::RenderTarget& target) {
    target.bindForDrawing();
    GLint fbo = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &fbo);
    return static_cast<GLuint>(fbo);
}

// Same-size copy of one rectangle of attachment 0 (no filtering: exact values).
void copyRect(const gl::RenderTarget& from, const gl::RenderTarget& to, const PixelRect& r) {
    const GLuint source = framebufferOf(from);
    framebufferOf(to); // binds `to` for drawing, attachment 0 as its only draw buffer
    glBindFramebuffer(GL_READ_FRAMEBUFFER, source);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glBlitFramebuffer(r.x, r.y, r.x + r.width, r.y + r.height, r.x, r.y, r.x + r.width, r.y + r.height,
                      GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

} // namespace

bool RegionComposite::fits(int width, int height) const {
    return composite_ && composite_->width() == width && composite_->height() == height;
}

void RegionComposite::freeze(const gl::RenderTarget* last, int width, int height) {
    if (last == composite_.get() && fits(width, height)) return; // already the last image
    auto next = std::make_unique<gl::RenderTarget>(width, height, std::vector<GLenum>{GL_RGBA32F});
    const bool scissor = glIsEnabled(GL_SCISSOR_TEST);
    glDisable(GL_SCISSOR_TEST);
    if (last && last->width() == width && last->height() == height) copyRect(*last, *next, {0, 0, width, height});
    else next->clear();
    if (scissor) glEnable(GL_SCISSOR_TEST);
    composite_ = std::move(next);
}

void RegionComposite::update(const gl::RenderTarget& result, const PixelRect& rect) {
    if (composite_ && &result != composite_.get()) copyRect(result, *composite_, rect);
}

} // namespace glint::renderer
