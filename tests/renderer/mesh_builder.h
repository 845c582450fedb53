#pragma once
// Triangle meshes built in code for the renderer's tests.
#include "scene/core/mesh.h"

#include <array>

namespace glint::test {

// A square of side `size` in the XZ plane, front face (counter-clockwise) towards +Y.
inline Mesh quadMesh(float size, MaterialId material) {
    const float s = 0.5f * size;
    Primitive p;
    p.positions = {{-s, 0.0f, -s}, {-s, 0.0f, s}, {s, 0.0f, s}, {s, 0.0f, -s}};
    p.normals.assign(4, glm::vec3(0.0f, 1.0f, 0.0f));
    p.indices = {0, 1, 2, 0, 2, 3};
    p.material = material;
    Mesh mesh;
    mesh.primitives.push_back(std::move(p));
    return mesh;
}

// An axis-aligned box of full extents `size` centred on the origin: 6 faces, 4 vertices each with
// the face normal, counter-clockwise seen from outside.
inline Mesh boxMesh(glm::vec3 size, MaterialId material) {
    Primitive p;
    const glm::vec3 h = 0.5f * size;
    const std::array<glm::vec3, 6> normals = {{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}};
    for (const glm::vec3& n : normals) {
        // Two axes spanning the face, ordered so that cross(u, v) = n.
        const glm::vec3 u = std::abs(n.x) > 0.5f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
        const glm::vec3 v = glm::cross(n, u);
        const glm::vec3 c = n * h;
        const glm::vec3 du = u * h, dv = v * h;
        const auto base = static_cast<std::uint32_t>(p.positions.size());
        for (const glm::vec2 corner : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
            p.positions.push_back(c + corner.x * du + corner.y * dv);
            p.normals.push_back(n);
        }
        p.indices.insert(p.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    p.material = material;
    Mesh mesh;
    mesh.primitives.push_back(std::move(p));
    return mesh;
}

} // namespace glint::test
