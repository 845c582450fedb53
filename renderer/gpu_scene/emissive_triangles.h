#pragma once
// Emissive mesh triangles in world space, for next-event estimation: chosen in proportion to their
// power (world area x emitted luminance), so the light pdf of a point on triangle i is
// luminance_i / totalPower per unit area, which the shader computes from the hit's material alone.
// CPU only.
#include <glm/glm.hpp>

#include <vector>

namespace glint::renderer {

struct EmissiveTriangles {
    std::vector<glm::vec4> texels; // 4 per triangle: p0, p1, p2 (world), emission radiance
    std::vector<float> cdf;        // count + 1 ascending values, 0 .. 1
    float totalPower = 0.0f;       // sum of area x luminance
    int count() const { return static_cast<int>(cdf.empty() ? 0 : cdf.size() - 1); }
    void add(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 emission);
    void finish(); // builds the CDF
private:
    std::vector<float> power_;
};

float emissionLuminance(glm::vec3 emission);

} // namespace glint::renderer
