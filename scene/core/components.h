#pragma once
// The one optional component a node may carry: a mesh instance, an analytic shape, a light or a camera.
#include "camera_path.h"
#include "ids.h"

#include <glm/glm.hpp>

#include <variant>

namespace glint {

struct MeshInstance {
    MeshId mesh{};
    friend bool operator==(const MeshInstance&, const MeshInstance&) = default;
};

// Analytic shapes are exact in the renderer; files carry them in a Glint extension plus a
// tessellated fallback mesh so other tools still see them. All live in the node's local space.
enum class ShapeKind { Sphere, Quad, Disk, Box, Cylinder, GroundPlane };

struct Shape {
    ShapeKind kind = ShapeKind::Sphere;
    float radius = 0.5f;              // sphere, disk, cylinder
    glm::vec3 size{1.0f, 1.0f, 1.0f}; // box: full extents; quad: size.x by size.z in the XZ plane, normal +Y
    float height = 1.0f;              // cylinder, along +Y, centred on the origin
    MaterialId material{};
    // Quad only: the paired portal's node (portal.h). A ray entering this quad leaves that one.
    NodeId portal{};
    // GroundPlane: the infinite plane y = 0 of the node's space, normal +Y. Kept out of any BVH.
    // Disk: radius in the XZ plane, normal +Y.
    friend bool operator==(const Shape&, const Shape&) = default;
};

enum class LightType { Sun, Point, Spot, Area };

// The emitting surface of an area light, in the light node's space: a rectangle or disk in its XY
// plane emitting along -Z from its front face only (as Blender's area lights and glTF's lights
// point), or a sphere emitting outwards.
enum class AreaShape { Rectangle, Disk, Sphere };

// Punctual lights are stored in glTF's photometric units (KHR_lights_punctual): lux for the sun,
// candela for point and spot; how they become radiance depends on the project's light-unit mode (see
// light_units.h). Area lights are stored as Blender gives them: power in watts, the radiant flux the
// emitter sends out, spread evenly (Lambertian) over its area: radiance P / (pi A) x colour.
struct Light {
    LightType type = LightType::Point;
    glm::vec3 color{1.0f};
    float intensity = 1.0f;               // lux (sun), candela (point, spot), watts (area)
    float range = 0.0f;                   // 0 = infinite
    float innerConeAngle = 0.0f;          // radians, spot only
    float outerConeAngle = 0.7853981634f; // radians (pi/4), spot only
    float angularDiameter = 0.0f;         // radians, sun only; 0 = a delta light (hard shadows)
    float radius = 0.0f;                  // metres: point and spot (0 = a delta light), area sphere
    AreaShape areaShape = AreaShape::Rectangle; // area only
    glm::vec2 size{1.0f, 1.0f};           // metres, area only: rectangle X by Y; a disk's diameter in x
    friend bool operator==(const Light&, const Light&) = default;
};

enum class Projection { Perspective, Orthographic };

struct Camera {
    Projection projection = Projection::Perspective;
    float yfov = 0.6911112f;  // radians (39.6 degrees, Blender's default 50 mm lens)
    float aspectRatio = 0.0f; // 0 = from the output size
    float znear = 0.01f;
    float zfar = 0.0f;        // 0 = infinite
    float xmag = 1.0f;        // orthographic half-extents in metres
    float ymag = 1.0f;
    float lensRadius = 0.0f;  // metres; 0 = pinhole
    float focusDistance = 1.0f; // metres
    float exposure = 0.0f;    // EV, + brighter
    CameraPath path;          // empty: no camera path
    friend bool operator==(const Camera&, const Camera&) = default;
};

using Component = std::variant<std::monostate, MeshInstance, Shape, Light, Camera>;

} // namespace glint
