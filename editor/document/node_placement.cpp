#include "node_placement.h"

#include "renderer/gpu_scene/light_units.h"

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

PortalPairPlacement placePortalPair(const ViewFocus& focus) {
    const double scale = std::isfinite(focus.scale) && focus.scale > 0.0 ? focus.scale : 1.0;
    PortalPairPlacement out;
    out.edge = float(2.0 * roundSize(kShapeShare * scale));
    Transform& a = out.a;
    // The quad's normal (+Y) turned to +Z: it stands upright, its Z extent now vertical.
    a.rotation = glm::angleAxis(0.5f * std::numbers::pi_v<float>, glm::vec3(1.0f, 0.0f, 0.0f));
    a.translation = glm::vec3(focus.point);
    if (focus.floor < 1e29) a.translation.y = float(focus.point.y - focus.floor + 0.5 * out.edge);
    out.b = a;
    a.translation.x -= 0.75f * out.edge;
    out.b.translation.x += 0.75f * out.edge;
    return out;
}

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

double newLightIrradiance() { return kBlenderLightCandela / renderer::lumensPerWatt / (kBlenderLightDistance * kBlenderLightDistance); }

float newAreaLightWatts(const Light& light, double distance) {
    if (!(distance > 0.0)) return 0.0f;
    const double h = distance;
    double irradiancePerWatt = 0.0; // at the point straight below, facing the light
    switch (light.areaShape) {
    case AreaShape::Rectangle: {
        // Four rectangles with a corner over the point: F = sum of (X atan(Y/X') + Y atan(X/Y')) / (2 pi).
        const double x = 0.5 * light.size.x / h, y = 0.5 * light.size.y / h;
        const double sx = std::sqrt(1.0 + x * x), sy = std::sqrt(1.0 + y * y);
        const double viewFactor = 4.0 * (x / sx * std::atan(y / sx) + y / sy * std::atan(x / sy)) / (2.0 * std::numbers::pi);
        irradiancePerWatt = viewFactor / (double(light.size.x) * light.size.y); // E = pi L F, L = P / (pi A)
        break;
    }
    case AreaShape::Disk: {
        const double r = 0.5 * light.size.x;
        irradiancePerWatt = r * r / (h * h + r * r) / (std::numbers::pi * r * r);
        break;
    }
    case AreaShape::Sphere: irradiancePerWatt = 1.0 / (4.0 * std::numbers::pi * h * h); break;
    }
    if (!(irradiancePerWatt > 0.0) || !std::isfinite(irradiancePerWatt)) return 0.0f;
    return float(newLightIrradiance() / irradiancePerWatt);
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
        const double free = std::max(0.0, focus.headroom - focus.clearFrom);
        const double height = focus.clearFrom + std::min(kLightHeight * scale, kHeadroomShare * free);
        out.worldFromNode.translation = glm::vec3(focus.point + glm::dvec3(0.0, height, 0.0));
        if (placed.type == LightType::Sun) {
            out.worldFromNode.rotation = sunRotation();
            placed.intensity = kNewSunLux;
        } else if (placed.type == LightType::Area) {
            // Sized like a new shape, facing down (a light shines along its -Z), as bright at the
            // focus as a new point light. A sphere's centre keeps its radius below the ceiling.
            const float s = float(roundSize(kShapeShare * scale));
            placed.size *= s;
            placed.radius *= s;
            double distance = height;
            if (placed.areaShape == AreaShape::Sphere) {
                distance = std::max(std::min(height, kHeadroomShare * focus.headroom - double(placed.radius)), 2.0 * placed.radius);
                out.worldFromNode.translation = glm::vec3(focus.point + glm::dvec3(0.0, distance, 0.0));
            }
            out.worldFromNode.rotation = glm::angleAxis(float(-std::numbers::pi / 2.0), glm::vec3(1.0f, 0.0f, 0.0f));
            placed.intensity = newAreaLightWatts(placed, distance);
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
