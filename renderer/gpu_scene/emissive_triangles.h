#pragma once
// Emissive mesh triangles in world space, for next-event estimation: chosen in proportion to their
// power (world area x emitted luminance), so the light pdf of a point on triangle i is
// luminance_i / totalPower per unit area, which the shader computes from the hit's material alone.
// A single-sided material (glTF doubleSided false) emits from its front face only: the side its
// world-space winding normal points to (the vertices are stored in that order); a double-sided one
// from both. An emissive-textured triangle is chosen by its area times the luminance of its
// material's mean emission (texture_refs.h, sampledEmission) and names its BVH slot, so that the
// shader reads the texel's emission at the sampled point. CPU only.
#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace glint::renderer {

// Where an emissive-textured triangle's texture coordinates come from: its slot in the flattened
// BVH (the shader interpolates the slot's vertex attributes) and whether p1 and p2 were swapped
// for a mirroring instance.
struct EmitterTexturing {
    std::uint32_t slot = 0;
    bool swapped = false;
};

struct EmissiveTriangles {
    static constexpr std::size_t texelsPerTriangle = 5; // EMISSIVE_TRIANGLE_TEXELS in emissive_lights.glsl
    // 5 per triangle: p0, p1, p2 (world, counter-clockwise seen from the front); the emission light
    // sampling assumes, with w = 1 for a two-sided emitter, 0 for one that emits from its front face
    // only; (slot / 65536, slot % 65536, 1 if textured, 1 if p1 and p2 were swapped), each exact
    // in a float.
    std::vector<glm::vec4> texels;
    std::vector<float> cdf;        // count + 1 ascending values, 0 .. 1
    float totalPower = 0.0f;       // sum of area x luminance
    int count() const { return static_cast<int>(cdf.empty() ? 0 : cdf.size() - 1); }
    void add(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 emission, bool twoSided = true,
             std::optional<EmitterTexturing> texturing = std::nullopt);
    void finish(); // builds the CDF
private:
    std::vector<float> power_;
};

float emissionLuminance(glm::vec3 emission);

} // namespace glint::renderer
