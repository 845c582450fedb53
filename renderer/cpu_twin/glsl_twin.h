#pragma once
// The C++ twin of the shared GLSL (shaders/common, shaders/sampling, shaders/bsdf): the same source
// files compiled as C++ through GLM, so that CPU tests check the code the GPU runs. This header
// supplies what GLSL has built in and C++ lacks (out-parameters, uint, sampler2D + texelFetch,
// array constructors).
// The files land in an unnamed namespace: GLSL functions cannot be marked inline, and internal
// linkage keeps each test's copy to itself.
#include "renderer/cpu_twin/ggx_energy_tables.h"

#include <array>
#include <cstdint>
#include <glm/glm.hpp>

namespace glint::twin {

using namespace glm;
using uint = std::uint32_t;

// A one-channel float texture as GLSL's texelFetch sees it: texel (x, y) at texels[y * width + x].
struct sampler2D {
    int width = 0;
    int height = 0;
    const float* texels = nullptr;
};

inline vec4 texelFetch(const sampler2D& texture, ivec2 p, int /*lod*/) {
    return vec4(texture.texels[p.y * texture.width + p.x], 0.0f, 0.0f, 1.0f);
}

#define OUT(T) T&
#define INOUT(T) T&
#define FLOAT_TABLE(name, n) const std::array<float, n> name = floatTable<n>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
namespace {
#include "common/math.glsl"
#include "common/rng.glsl"
#include "common/frame.glsl"
#include "sampling/warp.glsl"
#include "sampling/mis.glsl"
#include "sampling/distribution.glsl"
#include "sampling/environment_sampling.glsl"
#include "sampling/sphere_light.glsl"
#include "sampling/shape_emitter.glsl"
#include "sampling/phase.glsl"
#include "sampling/fog_density.glsl"
#include "bsdf/bsdf.glsl"
} // namespace
#pragma GCC diagnostic pop

#undef OUT
#undef INOUT
#undef FLOAT_TABLE

} // namespace glint::twin
