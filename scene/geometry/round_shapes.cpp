#include "round_shapes.h"

#include <algorithm>
#include <glm/gtc/constants.hpp>

#include <cmath>

namespace glint {

namespace {

// Around +Y counter-clockwise seen from above, starting at +X.
glm::vec3 around(float turn) {
    const float angle = 2.0f * glm::pi<float>() * turn;
    return {std::cos(angle), 0.0f, -std::sin(angle)};
}

} // namespace

void addSphere(PrimitiveBuilder& b, float radius, int segments) {
    const int rings = std::max(segments / 2, 2);
    const auto rowStart = [&](int ring) { return std::uint32_t(ring * (segments + 1)); };
    const std::uint32_t base = std::uint32_t(b.primitive.positions.size());
    for (int i = 0; i <= rings; ++i) {
        const float polar = glm::pi<float>() * float(i) / float(rings);
        for (int j = 0; j <= segments; ++j) {
            const float turn = float(j) / float(segments);
            const glm::vec3 direction = std::sin(polar) * around(turn) + glm::vec3(0.0f, std::cos(polar), 0.0f);
            b.vertex(radius * direction, direction, {turn, float(i) / float(rings)});
        }
    }
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            const std::uint32_t a = base + rowStart(i) + std::uint32_t(j), d = a + 1;
            const std::uint32_t below = base + rowStart(i + 1) + std::uint32_t(j), belowNext = below + 1;
            if (i > 0) b.triangle(a, belowNext, d);               // at the north pole a and d coincide
            if (i + 1 < rings) b.triangle(a, below, belowNext); // at the south pole below ones coincide
        }
}

void addCylinder(PrimitiveBuilder& b, float radius, float height, int segments) {
    const float half = 0.5f * height;
    const std::uint32_t base = std::uint32_t(b.primitive.positions.size());
    for (int j = 0; j <= segments; ++j) {
        const float turn = float(j) / float(segments);
        const glm::vec3 out = around(turn);
        b.vertex(radius * out + glm::vec3(0.0f, -half, 0.0f), out, {turn, 1.0f});
        b.vertex(radius * out + glm::vec3(0.0f, half, 0.0f), out, {turn, 0.0f});
    }
    for (int j = 0; j < segments; ++j) {
        const std::uint32_t bottom = base + 2 * std::uint32_t(j), top = bottom + 1;
        b.quad(bottom, bottom + 2, top + 2, top);
    }
    addDisk(b, {0.0f, half, 0.0f}, {1, 0, 0}, {0, 0, -1}, radius, segments);
    addDisk(b, {0.0f, -half, 0.0f}, {1, 0, 0}, {0, 0, 1}, radius, segments);
}

} // namespace glint
