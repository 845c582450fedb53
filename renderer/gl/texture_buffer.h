#pragma once
// A buffer texture (samplerBuffer / usamplerBuffer in GLSL): the GL 4.1 way to give fragment
// shaders large arrays. Sizes are checked against GL_MAX_TEXTURE_BUFFER_SIZE, which GL only
// guarantees to be 65,536 texels.
#include "renderer/gl/gl_objects.h"

#include <cstddef>
#include <string>

namespace glint::gl {

class TextureBuffer {
public:
    // `format`: GL_RGBA32F, GL_RGBA32UI, GL_R32UI, ... ; `texels` of `bytesPerTexel` each.
    // Throws std::runtime_error naming `what` when the driver's limit is exceeded.
    TextureBuffer(const std::string& what, GLenum format, const void* data, std::size_t texels, std::size_t bytesPerTexel);
    // Rewrites `count` texels from `first` on (glBufferSubData), keeping the buffer; the range must lie
    // inside it (std::logic_error otherwise).
    void update(std::size_t first, const void* data, std::size_t count);
    // Binds the buffer texture to `unit` and points the sampler uniform `location` at it.
    void bind(GLuint unit, GLint location) const;
    std::size_t texels() const { return texels_; }

private:
    Buffer buffer_;
    Texture texture_;
    std::size_t texels_ = 0;
    std::size_t bytesPerTexel_ = 0;
};

std::size_t maxTextureBufferTexels();

} // namespace glint::gl
