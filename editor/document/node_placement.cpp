#include "node_placement.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace glint::editor {

namespace {

// Blender's new point and spot lights are 1000 W, which its glTF importer reads from
// 1000 * 683 / (4 pi) cd; its default scene has that light 7.24 m from the origin it lights.
constexpr double kBlenderLightCandela = 1000.0 * 683.0 / (4.0 * std::numbers::pi);
constexpr double kBlenderLightDistance = 7.24;
constexpr double kShapeShare = 0.25;   // of the focus's scale
constexpr double kLightHeight = 0.6;   // of the focus's scale, above it
constexpr double kHeadroomShare = 0.8; // of the free space above the focus

// The sun's direction of travel: down at 50 degrees, from the side (a flat sun lights nothing).
glm::quat sunRotation() {
    const glm::quat down = glm::angleAxis(float(-50.0 * std::numbers::pi / 180.0), glm::vec3(1.0f, 0.0f, 0.0f));
    const glm::quat side = glm::angleAxis(float(30.0 * std::numbers::pi / 180.0), glm::vec3(0.0f, 1.0f, 0.0f));
    return side * down; // glTF lights shine along their node's -Z
}

Shape scaled(Shape shape, float s) {
    shape.radius *= s;
    shape.size *= s;
    shape.height *= s;
    return shape;
}

// How far a shape reaches below its centre; 0 for flat ones (a quad or disk on a floor would
// coincide with it).
double halfHeight(const Shape& shape) {
    switch (shape.kind) {
    case ShapeKind::Sphere: return shape.radius;
    case ShapeKind::Box: return 0.5 * shape.size.y;
    case ShapeKind::Cylinder: return 0.5 * shape.height;
    default: return 0.0;
    }
}

} // namespace

double roundSize(double metres) {
    if (!(metres > 0.0) || !std::isfinite(metres)) return 1.0;
    const double decade = std::pow(10.0, std::floor(std::log10(metres)));
    const double mantissa = metres / decade;
    return decade * (mantissa >= 5.0 ? 5.0 : mantissa >= 2.0 ? 2.0 : 1.0);
}

float newPointCandela(double distance) {
    const double ratio = distance / kBlenderLightDistance;
    return float(kBlenderLightCandela * ratio * ratio);
}

Placement placeNewNode(const Component& unit, const ViewFocus& focus) {
    Placement out{Transform{}, unit};
    const double scale = std::isfinite(focus.scale) && focus.scale > 0.0 ? focus.scale : 1.0;
    out.worldFromNode.translation = glm::vec3(focus.point);
    if (const auto* shape = std::get_if<Shape>(&unit)) {
        if (shape->kind == ShapeKind::GroundPlane) {
            out.worldFromNode.translation = glm::vec3(0.0f); // infinite: only its height would matter
        } else {
            const Shape sized = scaled(*shape, float(roundSize(kShapeShare * scale)));
            const double below = halfHeight(sized);
            if (below > 0.0 && focus.floor < 1e29) // resting on what is under the focus
                out.worldFromNode.translation.y = float(focus.point.y - focus.floor + below);
            out.component = sized;
        }
    } else if (const auto* light = std::get_if<Light>(&unit)) {
        Light placed = *light;
        const double height = std::min(kLightHeight * scale, kHeadroomShare * focus.headroom);
        out.worldFromNode.translation = glm::vec3(focus.point + glm::dvec3(0.0, height, 0.0));
        if (placed.type == LightType::Sun) {
            out.worldFromNode.rotation = sunRotation();
            placed.intensity = kNewSunLux;
        } else {
            if (placed.type == LightType::Spot) // straight down
                out.worldFromNode.rotation = glm::angleAxis(float(-std::numbers::pi / 2.0), glm::vec3(1.0f, 0.0f, 0.0f));
            placed.intensity = newPointCandela(height);
        }
        out.component = placed;
    }
    return out;
}

} // namespace glint::editor
