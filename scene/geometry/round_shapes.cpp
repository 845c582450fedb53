#include "round_shapes.h"

#include <algorithm>
#include <glm/gtc/constants.hpp>

#include <cmath>

namespace glint {

namespace {

// A point of the unit sphere: ring i of `rings` from the north pole, step j around Y. The poles
// are exact, so the triangles meeting there share their corner bit for bit.
glm::vec3 onSphere(int i, int rings, int j, int segments) {
    if (i == 0) return {0.0f, 1.0f, 0.0f};
    if (i == rings) return {0.0f, -1.0f, 0.0f};
    const float polar = glm::pi<float>() * float(i) / float(rings);
    return std::sin(polar) * aroundY(j, segments) + glm::vec3(0.0f, std::cos(polar), 0.0f);
}

} // namespace

void addSphere(PrimitiveBuilder& b, float radius, int segments) {
    const int rings = std::max(segments / 2, 2);
    const auto rowStart = [&](int ring) { return std::uint32_t(ring * (segments + 1)); };
    const std::uint32_t base = std::uint32_t(b.primitive.positions.size());
    for (int i = 0; i <= rings; ++i) {
        for (int j = 0; j <= segments; ++j) {
            const glm::vec3 direction = onSphere(i, rings, j, segments);
            b.vertex(radius * direction, direction, {float(j) / float(segments), float(i) / float(rings)});
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
        const glm::vec3 out = aroundY(j, segments);
        b.vertex(glm::vec3(0.0f, -half, 0.0f) + radius * out, out, {turn, 1.0f});
        b.vertex(glm::vec3(0.0f, half, 0.0f) + radius * out, out, {turn, 0.0f});
    }
    for (int j = 0; j < segments; ++j) {
        const std::uint32_t bottom = base + 2 * std::uint32_t(j), top = bottom + 1;
        b.quad(bottom, bottom + 2, top + 2, top);
    }
    addDiskXZ(b, {0.0f, half, 0.0f}, radius, segments, true);
    addDiskXZ(b, {0.0f, -half, 0.0f}, radius, segments, false);
}

} // namespace glint
