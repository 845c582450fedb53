#include "renderer/gpu_scene/emissive_triangles.h"

#include <cmath>

namespace glint::renderer {

float emissionLuminance(glm::vec3 e) { return 0.2126f * e.x + 0.7152f * e.y + 0.0722f * e.z; }

void EmissiveTriangles::add(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 emission, bool twoSided,
                            std::optional<EmitterTexturing> texturing) {
    const float area = 0.5f * glm::length(glm::cross(p1 - p0, p2 - p0));
    const float power = area * emissionLuminance(emission);
    if (!(power > 0.0f) || !std::isfinite(power)) return; // degenerate or black: never sampled
    const EmitterTexturing t = texturing.value_or(EmitterTexturing{});
    texels.insert(texels.end(), {glm::vec4(p0, 0.0f), glm::vec4(p1, 0.0f), glm::vec4(p2, 0.0f), glm::vec4(emission, twoSided ? 1.0f : 0.0f),
                                 glm::vec4(static_cast<float>(t.slot >> 16u), static_cast<float>(t.slot & 0xffffu),
                                           texturing ? 1.0f : 0.0f, t.swapped ? 1.0f : 0.0f)});
    power_.push_back(power);
}

void EmissiveTriangles::finish() {
    cdf.assign(1, 0.0f);
    double sum = 0.0;
    for (const float p : power_) sum += p;
    totalPower = static_cast<float>(sum);
    double running = 0.0;
    for (const float p : power_) {
        running += p;
        cdf.push_back(static_cast<float>(running / sum));
    }
    if (cdf.size() > 1) cdf.back() = 1.0f;
    else cdf.clear();
}

} // namespace glint::renderer
