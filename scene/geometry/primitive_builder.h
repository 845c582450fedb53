#pragma once
// Appending vertices and counter-clockwise triangles to a Primitive while tessellating shapes.
#include "scene/core/mesh.h"

namespace glint {

struct PrimitiveBuilder {
    Primitive primitive;

    std::uint32_t vertex(const glm::vec3& position, const glm::vec3& normal, const glm::vec2& uv) {
        primitive.positions.push_back(position);
        primitive.normals.push_back(normal);
        primitive.uv0.push_back(uv);
        return std::uint32_t(primitive.positions.size() - 1);
    }
    // Counter-clockwise seen from the side the normals point to.
    void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        primitive.indices.insert(primitive.indices.end(), {a, b, c});
    }
    void quad(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
        triangle(a, b, c);
        triangle(a, c, d);
    }
};

// A flat rectangle centred on `centre` spanning +-halfU along u and +-halfV along v, facing
// cross(u, v). uv (0, 0) at the -u, +v corner (glTF's top left when v points up).
void addRectangle(PrimitiveBuilder& b, const glm::vec3& centre, const glm::vec3& u, const glm::vec3& v);

// The unit circle in the XZ plane, counter-clockwise seen from +Y, starting at +X. Step j and
// j + segments give the same bits, so seams and shared rims match exactly (watertight meshes).
glm::vec3 aroundY(int j, int segments);

// A disc of `segments` triangles in the plane y = centre.y with `radius`, facing +Y or -Y.
// Its rim vertices are bit-identical to centre + radius * aroundY(j, segments).
void addDiskXZ(PrimitiveBuilder& b, const glm::vec3& centre, float radius, int segments, bool facingUp);

} // namespace glint
