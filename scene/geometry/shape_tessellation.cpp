#include "geometry.h"

#include "primitive_builder.h"
#include "round_shapes.h"

#include <algorithm>

namespace glint {

namespace {

const glm::vec3 kX{1, 0, 0}, kY{0, 1, 0}, kZ{0, 0, 1};
// A bound on the mesh size (a sphere of 4096 segments has 16.7 M triangles).
constexpr int kMaxSegments = 4096;

// Each face's (u, v) with cross(u, v) pointing out of the box.
void addBox(PrimitiveBuilder& b, const glm::vec3& size) {
    const glm::vec3 h = 0.5f * size;
    addRectangle(b, {h.x, 0, 0}, -h.z * kZ, h.y * kY);
    addRectangle(b, {-h.x, 0, 0}, h.z * kZ, h.y * kY);
    addRectangle(b, {0, h.y, 0}, h.x * kX, -h.z * kZ);
    addRectangle(b, {0, -h.y, 0}, h.x * kX, h.z * kZ);
    addRectangle(b, {0, 0, h.z}, h.x * kX, h.y * kY);
    addRectangle(b, {0, 0, -h.z}, -h.x * kX, h.y * kY);
}

// A rectangle in the XZ plane facing +Y, `width` along X and `depth` along Z.
void addUpFacingRectangle(PrimitiveBuilder& b, float width, float depth) {
    addRectangle(b, glm::vec3(0.0f), 0.5f * width * kX, -0.5f * depth * kZ);
}

} // namespace

Primitive tessellateShape(const Shape& shape, int segments, float groundExtent) {
    segments = std::clamp(segments, 3, kMaxSegments);
    PrimitiveBuilder b;
    switch (shape.kind) {
    case ShapeKind::Sphere: addSphere(b, shape.radius, segments); break;
    case ShapeKind::Quad: addUpFacingRectangle(b, shape.size.x, shape.size.z); break;
    case ShapeKind::Disk: addDiskXZ(b, glm::vec3(0.0f), shape.radius, segments, true); break;
    case ShapeKind::Box: addBox(b, shape.size); break;
    case ShapeKind::Cylinder: addCylinder(b, shape.radius, shape.height, segments); break;
    case ShapeKind::GroundPlane: addUpFacingRectangle(b, groundExtent, groundExtent); break;
    }
    b.primitive.material = shape.material;
    generateTangents(b.primitive);
    return std::move(b.primitive);
}

} // namespace glint
