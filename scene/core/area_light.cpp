#include "scene/core/area_light.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <numbers>

namespace glint {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// Area scale of the surface element with local unit normal n under the linear map m (inverse
// `inv`): |det m| |inv^T n|.
float areaScale(const glm::mat3& m, const glm::mat3& inv, glm::vec3 n) {
    return std::abs(glm::determinant(m)) * glm::length(glm::transpose(inv) * n);
}

// Area scale of the plane spanned by the unit vectors a and b.
float planeScale(const glm::mat3& m, glm::vec3 a, glm::vec3 b) { return glm::length(glm::cross(m * a, m * b)); }

} // namespace

Shape areaLightShape(const Light& light) {
    Shape shape;
    switch (light.areaShape) {
    case AreaShape::Rectangle:
        shape.kind = ShapeKind::Quad;
        shape.size = {light.size.x, 1.0f, light.size.y};
        break;
    case AreaShape::Disk:
        shape.kind = ShapeKind::Disk;
        shape.radius = 0.5f * light.size.x;
        break;
    case AreaShape::Sphere:
        shape.kind = ShapeKind::Sphere;
        shape.radius = light.radius;
        break;
    }
    return shape;
}

glm::mat4 lightFromAreaShape(const Light& light) {
    if (light.areaShape == AreaShape::Sphere) return glm::mat4(1.0f);
    return glm::rotate(glm::mat4(1.0f), -0.5f * kPi, glm::vec3(1.0f, 0.0f, 0.0f));
}

float shapeArea(const Shape& shape, const glm::mat4& worldFromShape) {
    const glm::mat3 m(worldFromShape);
    const glm::vec3 x(1.0f, 0.0f, 0.0f), y(0.0f, 1.0f, 0.0f), z(0.0f, 0.0f, 1.0f);
    switch (shape.kind) {
    case ShapeKind::Quad: return shape.size.x * shape.size.z * planeScale(m, x, z);
    case ShapeKind::Disk: return kPi * shape.radius * shape.radius * planeScale(m, x, z);
    case ShapeKind::Box:
        return 2.0f * (shape.size.y * shape.size.z * planeScale(m, y, z) + shape.size.x * shape.size.z * planeScale(m, x, z) +
                       shape.size.x * shape.size.y * planeScale(m, x, y));
    case ShapeKind::GroundPlane: return 0.0f;
    case ShapeKind::Sphere:
    case ShapeKind::Cylinder: break;
    }
    const glm::mat3 inv = glm::inverse(m);
    constexpr int kSteps = 128; // midpoint rule around the axis (and over latitude)
    const float r = shape.radius;
    double sum = 0.0;
    if (shape.kind == ShapeKind::Cylinder) {
        for (int j = 0; j < kSteps; ++j) {
            const float phi = 2.0f * kPi * (float(j) + 0.5f) / float(kSteps);
            sum += double(areaScale(m, inv, {std::cos(phi), 0.0f, std::sin(phi)}));
        }
        const double side = sum * double(2.0f * kPi / float(kSteps)) * double(r) * double(shape.height);
        return float(side + 2.0 * double(kPi * r * r * planeScale(m, x, z)));
    }
    for (int i = 0; i < kSteps / 2; ++i) {
        const float theta = kPi * (float(i) + 0.5f) / float(kSteps / 2);
        for (int j = 0; j < kSteps; ++j) {
            const float phi = 2.0f * kPi * (float(j) + 0.5f) / float(kSteps);
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
            sum += double(areaScale(m, inv, n)) * double(std::sin(theta));
        }
    }
    // Midpoint weights sum to 4 pi for the unit sphere only approximately: normalise by that sum.
    double weights = 0.0;
    for (int i = 0; i < kSteps / 2; ++i) weights += double(kSteps) * std::sin(double(kPi) * (i + 0.5) / (kSteps / 2));
    return float(sum / weights * 4.0 * std::numbers::pi * double(r) * double(r));
}

float areaLightArea(const Light& light, const glm::mat4& worldFromLight) {
    return shapeArea(areaLightShape(light), worldFromLight * lightFromAreaShape(light));
}

glm::vec3 areaLightRadiance(const Light& light, float area) {
    if (!(area > 0.0f) || !std::isfinite(area)) return glm::vec3(0.0f);
    return light.color * (light.intensity / (kPi * area));
}

} // namespace glint
