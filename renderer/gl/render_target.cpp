#include "renderer/gl/render_target.h"

#include <stdexcept>
#include <string>

namespace glint::gl {
namespace {

GLenum externalFormat(GLenum internal) {
    switch (internal) {
    case GL_R32F: return GL_RED;
    case GL_RG32F: return GL_RG;
    default: return GL_RGBA;
    }
}

template <class T>
std::vector<T> readPixels(GLuint fbo, int attachment, int width, int height, GLenum type) {
    std::vector<T> pixels(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    glReadBuffer(GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(attachment));
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width, height, GL_RGBA, type, pixels.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    return pixels;
}

} // namespace

RenderTarget::RenderTarget(int width, int height, const std::vector<GLenum>& formats, GLuint depthTexture)
    : width_(width), height_(height), fbo_(makeFramebuffer()) {
    if (width <= 0 || height <= 0) throw std::runtime_error("render target size must be positive");
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.get());
    for (std::size_t i = 0; i < formats.size(); ++i) {
        Texture texture = makeTexture();
        glBindTexture(GL_TEXTURE_2D, texture.get());
        glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(formats[i]), width, height, 0, externalFormat(formats[i]), GL_FLOAT, nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i), GL_TEXTURE_2D, texture.get(), 0);
        textures_.push_back(std::move(texture));
    }
    if (depthTexture) glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depthTexture, 0);
    glBindTexture(GL_TEXTURE_2D, 0);
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("float render target incomplete (status 0x" + std::to_string(status) + ")");
}

void RenderTarget::bindForDrawing() const {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.get());
    std::vector<GLenum> buffers;
    for (std::size_t i = 0; i < textures_.size(); ++i) buffers.push_back(GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i));
    glDrawBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
    glViewport(0, 0, width_, height_);
}

void RenderTarget::bindTexture(int attachment, GLuint unit, GLint location) const {
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D, textures_.at(static_cast<std::size_t>(attachment)).get());
    glUniform1i(location, static_cast<GLint>(unit));
}

void RenderTarget::clear() const {
    bindForDrawing();
    const GLfloat zero[4] = {0, 0, 0, 0};
    for (std::size_t i = 0; i < textures_.size(); ++i) glClearBufferfv(GL_COLOR, static_cast<GLint>(i), zero);
}

std::vector<float> RenderTarget::readRgba(int attachment) const {
    return readPixels<float>(fbo_.get(), attachment, width_, height_, GL_FLOAT);
}

std::vector<unsigned char> RenderTarget::readRgba8(int attachment) const {
    return readPixels<unsigned char>(fbo_.get(), attachment, width_, height_, GL_UNSIGNED_BYTE);
}

} // namespace glint::gl
