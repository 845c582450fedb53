#pragma once
// Emissive mesh triangles in world space, for next-event estimation: chosen in proportion to their
// power (world area x emitted luminance), so the light pdf of a point on triangle i is
// luminance_i / totalPower per unit area, which the shader computes from the hit's material alone.
// A single-sided material (glTF doubleSided false) emits from its front face only: the side its
// world-space winding normal points to (the vertices are stored in that order); a double-sided one
// from both. CPU only.
#include <glm/glm.hpp>

#include <vector>

namespace glint::renderer {

struct EmissiveTriangles {
    // 4 per triangle: p0, p1, p2 (world, counter-clockwise seen from the front), emission radiance
    // with w = 1 for a two-sided emitter, 0 for one that emits from its front face only.
    std::vector<glm::vec4> texels;
    std::vector<float> cdf;        // count + 1 ascending values, 0 .. 1
    float totalPower = 0.0f;       // sum of area x luminance
    int count() const { return static_cast<int>(cdf.empty() ? 0 : cdf.size() - 1); }
    void add(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 emission, bool twoSided = true);
    void finish(); // builds the CDF
private:
    std::vector<float> power_;
};

float emissionLuminance(glm::vec3 emission);

} // namespace glint::renderer
