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

glm::vec3 aroundY(int j, int segments) {
    const float angle = 2.0f * glm::pi<float>() * float(j % segments) / float(segments);
    return {std::cos(angle), 0.0f, -std::sin(angle)};
}

// Seen from below the rim runs the other way round, and uv is mirrored so the texture is not.
void addDiskXZ(PrimitiveBuilder& b, const glm::vec3& centre, float radius, int segments, bool facingUp) {
    const glm::vec3 normal(0.0f, facingUp ? 1.0f : -1.0f, 0.0f);
    const std::uint32_t middle = b.vertex(centre, normal, {0.5f, 0.5f});
    const std::uint32_t first = std::uint32_t(b.primitive.positions.size());
    for (int j = 0; j < segments; ++j) {
        const glm::vec3 unit = aroundY(j, segments);
        b.vertex(centre + radius * unit, normal, {0.5f + 0.5f * unit.x, 0.5f + (facingUp ? 0.5f : -0.5f) * unit.z});
    }
    for (int j = 0; j < segments; ++j) {
        const auto here = first + std::uint32_t(j), next = first + std::uint32_t((j + 1) % segments);
        if (facingUp) b.triangle(middle, here, next);
        else b.triangle(middle, next, here);
    }
}

} // namespace glint
