#pragma once
// Keeps the caller's scissor (its box and whether it is on) across work done in bands of rows:
// set on construction, put back on destruction.
#include <epoxy/gl.h>

namespace glint::gl {

class ScissorGuard {
public:
    ScissorGuard() : enabled_(glIsEnabled(GL_SCISSOR_TEST)) { glGetIntegerv(GL_SCISSOR_BOX, box_); }
    ~ScissorGuard() {
        glScissor(box_[0], box_[1], box_[2], box_[3]);
        if (!enabled_) glDisable(GL_SCISSOR_TEST);
    }
    ScissorGuard(const ScissorGuard&) = delete;
    ScissorGuard& operator=(const ScissorGuard&) = delete;

private:
    GLboolean enabled_;
    GLint box_[4] = {0, 0, 0, 0};
};

} // namespace glint::gl
