#pragma once
// A TextureSet on the GPU: one 2D texture array per bucket (GL_SRGB8_ALPHA8 for colour data, so
// sampling decodes sRGB exactly; GL_RGBA8 for linear data), every mip level uploaded from the CPU
// chain. Filtering is trilinear with GL_REPEAT; the shader applies each texture's own wrap and
// filter modes (shaders/textures/texture_sample.glsl).
#include "renderer/gl/gl_objects.h"
#include "renderer/gl/shader_program.h"
#include "renderer/gpu_scene/texture_set.h"

#include <glm/glm.hpp>

#include <vector>

namespace glint::renderer {

inline constexpr int maxTextureArrays = 3; // sampler units 13..15 (GpuScene's budget of 16)

// The driver's limits for TextureSet building (array layers, texture size).
TextureLimits queryTextureLimits();

class TextureArrays {
public:
    TextureArrays() = default;
    explicit TextureArrays(const TextureSet& set);
    bool empty() const { return arrays_.empty(); }
    // Binds bucket i to unit firstUnit + i and sets uTextureArray<i> and uTextureArraySize<i>.
    void bind(const gl::ShaderProgram& program, GLuint firstUnit) const;

private:
    std::vector<gl::Texture> arrays_;
    std::vector<glm::ivec2> sizes_;
};

} // namespace glint::renderer
