#include "renderer/gpu_scene/texture_arrays.h"

#include <algorithm>
#include <string>

namespace glint::renderer {
namespace {

gl::Texture uploadBucket(const TextureBucket& bucket) {
    gl::Texture texture = gl::makeTexture();
    glBindTexture(GL_TEXTURE_2D_ARRAY, texture.get());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    const auto levels = bucket.layers.front()->size();
    const GLint internalFormat = bucket.srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8;
    // Each level is allocated, then filled layer by layer straight from the (cached) chains: no
    // copy of the whole array on the CPU.
    for (std::size_t level = 0; level < levels; ++level) {
        const TextureLevel& first = (*bucket.layers.front())[level];
        const auto layers = static_cast<GLsizei>(bucket.layers.size());
        glTexImage3D(GL_TEXTURE_2D_ARRAY, static_cast<GLint>(level), internalFormat, first.width, first.height, layers, 0,
                     GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
        for (GLsizei layer = 0; layer < layers; ++layer)
            glTexSubImage3D(GL_TEXTURE_2D_ARRAY, static_cast<GLint>(level), 0, 0, layer, first.width, first.height, 1, GL_RGBA,
                            GL_UNSIGNED_BYTE, (*bucket.layers[static_cast<std::size_t>(layer)])[level].rgba.data());
    }
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_BASE_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, static_cast<GLint>(levels) - 1);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    return texture;
}

} // namespace

TextureLimits queryTextureLimits() {
    GLint layers = 0, size = 0;
    glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &layers);
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &size);
    TextureLimits limits;
    limits.maxBuckets = maxTextureArrays;
    limits.maxLayers = std::min(std::max(layers, 1), 2048);
    limits.maxSize = std::min(std::max(size, 1), 8192);
    return limits;
}

TextureArrays::TextureArrays(const TextureSet& set) {
    for (const TextureBucket& bucket : set.buckets) {
        arrays_.push_back(uploadBucket(bucket));
        sizes_.emplace_back(bucket.width, bucket.height);
    }
}

void TextureArrays::bind(const gl::ShaderProgram& program, GLuint firstUnit) const {
    for (std::size_t i = 0; i < arrays_.size(); ++i) {
        const GLuint unit = firstUnit + static_cast<GLuint>(i);
        glActiveTexture(GL_TEXTURE0 + unit);
        glBindTexture(GL_TEXTURE_2D_ARRAY, arrays_[i].get());
        const std::string index = std::to_string(i);
        glUniform1i(program.uniform(("uTextureArray" + index).c_str()), static_cast<GLint>(unit));
        glUniform2i(program.uniform(("uTextureArraySize" + index).c_str()), sizes_[i].x, sizes_[i].y);
    }
}

} // namespace glint::renderer
