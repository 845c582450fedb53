#include "primitive_builder.h"

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace glint {

void addRectangle(PrimitiveBuilder& b, const glm::vec3& centre, const glm::vec3& u, const glm::vec3& v) {
    const glm::vec3 normal = glm::normalize(glm::cross(u, v));
    const std::uint32_t lowLow = b.vertex(centre - u - v, normal, {0.0f, 1.0f});
    const std::uint32_t highLow = b.vertex(centre + u - v, normal, {1.0f, 1.0f});
    const std::uint32_t highHigh = b.vertex(centre + u + v, normal, {1.0f, 0.0f});
    const std::uint32_t lowHigh = b.vertex(centre - u + v, normal, {0.0f, 0.0f});
    b.quad(lowLow, highLow, highHigh, lowHigh);
}

void addDisk(PrimitiveBuilder& b, const glm::vec3& centre, const glm::vec3& u, const glm::vec3& v, float radius,
             int segments) {
    const glm::vec3 normal = glm::cross(u, v);
    const std::uint32_t middle = b.vertex(centre, normal, {0.5f, 0.5f});
    const std::uint32_t first = std::uint32_t(b.primitive.positions.size());
    for (int j = 0; j < segments; ++j) {
        const float angle = 2.0f * glm::pi<float>() * float(j) / float(segments);
        const float c = std::cos(angle), s = std::sin(angle);
        b.vertex(centre + radius * (c * u + s * v), normal, {0.5f + 0.5f * c, 0.5f - 0.5f * s});
    }
    for (int j = 0; j < segments; ++j)
        b.triangle(middle, first + std::uint32_t(j), first + std::uint32_t((j + 1) % segments));
}

} // namespace glint
