#include "editor/viewport/shape_intersect.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace glint::editor {

namespace {

bool accept(float t, float& tMax) {
    if (!(t > 0.0f) || !(t < tMax)) return false;
    tMax = t;
    return true;
}

// Smallest root of a t^2 + 2 b t + c = 0 that is accepted.
bool quadratic(float a, float b, float c, float& tMax, const auto& inside) {
    const float disc = b * b - a * c;
    if (disc < 0.0f || a == 0.0f) return false;
    const float s = std::sqrt(disc);
    for (const float t : {(-b - s) / a, (-b + s) / a})
        if (t > 0.0f && t < tMax && inside(t)) return accept(t, tMax);
    return false;
}

// The plane y = 0 with a test of the local hit point's x, z.
bool planeY(const bvh::Ray& r, float& tMax, const auto& inside) {
    if (r.direction.y == 0.0f) return false;
    const float t = -r.origin.y / r.direction.y;
    if (!(t > 0.0f && t < tMax)) return false;
    const glm::vec3 p = r.origin + t * r.direction;
    return inside(p.x, p.z) && accept(t, tMax);
}

bool box(const bvh::Ray& r, const glm::vec3& lo, const glm::vec3& hi, float& tMax) {
    float t0 = 0.0f, t1 = tMax;
    for (int a = 0; a < 3; ++a) {
        const float inv = 1.0f / r.direction[a];
        float tn = (lo[a] - r.origin[a]) * inv, tf = (hi[a] - r.origin[a]) * inv;
        if (tn > tf) std::swap(tn, tf);
        t0 = std::max(t0, tn);
        t1 = std::min(t1, tf);
        if (t0 > t1) return false;
    }
    return accept(t0 > 0.0f ? t0 : t1, tMax);
}

bool cylinder(const bvh::Ray& r, float radius, float height, float& tMax) {
    const float h = 0.5f * height;
    const glm::vec3& o = r.origin;
    const glm::vec3& d = r.direction;
    bool hit = quadratic(d.x * d.x + d.z * d.z, o.x * d.x + o.z * d.z, o.x * o.x + o.z * o.z - radius * radius, tMax,
                         [&](float t) { return std::abs(o.y + t * d.y) <= h; });
    for (const float y : {-h, h}) {
        bvh::Ray shifted{o - glm::vec3(0.0f, y, 0.0f), d};
        hit |= planeY(shifted, tMax, [&](float x, float z) { return x * x + z * z <= radius * radius; });
    }
    return hit;
}

} // namespace

bool intersectShape(const Shape& shape, const bvh::Ray& r, float& tMax) {
    switch (shape.kind) {
    case ShapeKind::Sphere: {
        const glm::vec3& o = r.origin;
        const glm::vec3& d = r.direction;
        return quadratic(glm::dot(d, d), glm::dot(o, d), glm::dot(o, o) - shape.radius * shape.radius, tMax,
                         [](float) { return true; });
    }
    case ShapeKind::Quad:
        return planeY(r, tMax, [&](float x, float z) { return std::abs(x) <= 0.5f * shape.size.x && std::abs(z) <= 0.5f * shape.size.z; });
    case ShapeKind::Disk:
        return planeY(r, tMax, [&](float x, float z) { return x * x + z * z <= shape.radius * shape.radius; });
    case ShapeKind::Box:
        return box(r, -0.5f * shape.size, 0.5f * shape.size, tMax);
    case ShapeKind::Cylinder:
        return cylinder(r, shape.radius, shape.height, tMax);
    case ShapeKind::GroundPlane:
        return false;
    }
    return false;
}

bool intersectGroundPlane(const bvh::Ray& r, float& tMax) {
    return planeY(r, tMax, [](float, float) { return true; });
}

bvh::Aabb shapeBounds(const Shape& shape) {
    const float eps = 1e-4f; // flat shapes still get a box with volume
    switch (shape.kind) {
    case ShapeKind::Sphere: return {glm::vec3(-shape.radius), glm::vec3(shape.radius)};
    case ShapeKind::Quad: return {glm::vec3(-0.5f * shape.size.x, -eps, -0.5f * shape.size.z), glm::vec3(0.5f * shape.size.x, eps, 0.5f * shape.size.z)};
    case ShapeKind::Disk: return {glm::vec3(-shape.radius, -eps, -shape.radius), glm::vec3(shape.radius, eps, shape.radius)};
    case ShapeKind::Box: return {-0.5f * shape.size, 0.5f * shape.size};
    case ShapeKind::Cylinder:
        return {glm::vec3(-shape.radius, -0.5f * shape.height, -shape.radius), glm::vec3(shape.radius, 0.5f * shape.height, shape.radius)};
    case ShapeKind::GroundPlane: return {};
    }
    return {};
}

} // namespace glint::editor
