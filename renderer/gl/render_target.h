#pragma once
// A framebuffer with float colour attachments of one size, and read-back of any attachment.
#include "renderer/gl/gl_objects.h"

#include <vector>

namespace glint::gl {

class RenderTarget {
public:
    // One texture per entry of `formats` (GL_RGBA32F, GL_R32F, ...), attached in order, and
    // `depthTexture` (a depth texture of the same size that the caller owns and keeps alive), if any.
    RenderTarget(int width, int height, const std::vector<GLenum>& formats, GLuint depthTexture = 0);
    void bindForDrawing() const; // binds the FBO, all draw buffers and the viewport
    void bindTexture(int attachment, GLuint unit, GLint location) const;
    void clear() const; // every attachment to 0
    // RGBA floats, rows bottom-up as GL stores them.
    std::vector<float> readRgba(int attachment) const;
    // For GL_RGBA8 attachments: bytes, rows bottom-up.
    std::vector<unsigned char> readRgba8(int attachment) const;
    int width() const { return width_; }
    int height() const { return height_; }

private:
    int width_;
    int height_;
    Framebuffer fbo_;
    std::vector<Texture> textures_;
};

} // namespace glint::gl
