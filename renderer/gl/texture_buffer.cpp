#include "renderer/gl/texture_buffer.h"

#include <stdexcept>

namespace glint::gl {

std::size_t maxTextureBufferTexels() {
    GLint limit = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &limit);
    return static_cast<std::size_t>(limit);
}

TextureBuffer::TextureBuffer(const std::string& what, GLenum format, const void* data, std::size_t texels,
                             std::size_t bytesPerTexel)
    : buffer_(makeBuffer()), texture_(makeTexture()), texels_(texels), bytesPerTexel_(bytesPerTexel) {
    const std::size_t limit = maxTextureBufferTexels();
    if (texels > limit)
        throw std::runtime_error(what + " needs " + std::to_string(texels) + " texels in a texture buffer, but this GPU allows " +
                                 std::to_string(limit) + " (GL_MAX_TEXTURE_BUFFER_SIZE)");
    // An empty buffer texture is legal, but some drivers dislike size 0: keep one zero texel.
    const std::size_t bytes = std::max<std::size_t>(texels * bytesPerTexel, bytesPerTexel);
    glBindBuffer(GL_TEXTURE_BUFFER, buffer_.get());
    glBufferData(GL_TEXTURE_BUFFER, static_cast<GLsizeiptr>(bytes), nullptr, GL_STATIC_DRAW);
    if (texels > 0) glBufferSubData(GL_TEXTURE_BUFFER, 0, static_cast<GLsizeiptr>(texels * bytesPerTexel), data);
    glBindTexture(GL_TEXTURE_BUFFER, texture_.get());
    glTexBuffer(GL_TEXTURE_BUFFER, format, buffer_.get());
    glBindTexture(GL_TEXTURE_BUFFER, 0);
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
}

void TextureBuffer::update(std::size_t first, const void* data, std::size_t count) {
    if (first + count > texels_ || first + count < first) throw std::logic_error("TextureBuffer::update: outside the buffer");
    if (count == 0) return;
    glBindBuffer(GL_TEXTURE_BUFFER, buffer_.get());
    glBufferSubData(GL_TEXTURE_BUFFER, static_cast<GLintptr>(first * bytesPerTexel_), static_cast<GLsizeiptr>(count * bytesPerTexel_), data);
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
}

void TextureBuffer::bind(GLuint unit, GLint location) const {
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_BUFFER, texture_.get());
    glUniform1i(location, static_cast<GLint>(unit));
}

} // namespace glint::gl
