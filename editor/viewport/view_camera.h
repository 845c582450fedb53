#pragma once
// The viewport's own camera: an orbit camera (a target, a distance and two angles) that also
// flies. It is editor state, not document content: navigating never dirties the file until the
// user turns the view into a scene camera. Pure math (no Qt, no GL), tested without a window.
#include "renderer/bvh/aabb.h"
#include "renderer/bvh/ray.h"
#include "scene/core/camera_path.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace glint::editor {

struct ViewCamera {
    glm::dvec3 target{0.0};
    double distance = 5.0;
    double yaw = 0.0;   // radians about +Y; 0 puts the camera on +Z looking along -Z (glTF's default)
    double pitch = 0.0; // radians, + looks down from above; kept inside (-pi/2, pi/2)
    float yfov = 0.6911112f;

    glm::dvec3 position() const;
    glm::dquat orientation() const; // cameraWorldFromLocal's rotation
    glm::dvec3 forward() const;     // unit, the view direction (-Z of the camera)
    glm::dvec3 right() const;
    glm::dvec3 up() const;
    glm::mat4 worldFromCamera() const;

    friend bool operator==(const ViewCamera&, const ViewCamera&) = default;
};

// Orbit about the target: dx/dy in pixels, `radiansPerPixel` the speed.
void orbit(ViewCamera& camera, double dx, double dy, double radiansPerPixel = 0.008);
// Moves the target in the view plane so the point at the target's depth follows the mouse.
void pan(ViewCamera& camera, double dx, double dy, int viewportHeight);
// Dolly towards the target; steps > 0 zooms in (one wheel notch = 1 step).
void zoom(ViewCamera& camera, double steps);
// Fly: look around from a fixed position (pixels) ...
void look(ViewCamera& camera, double dx, double dy, double radiansPerPixel = 0.004);
// ... and move in the camera's frame (x right, y up, z forward), in metres.
void fly(ViewCamera& camera, const glm::dvec3& cameraSpaceMove);
// Fits a sphere into the view (frame selection / frame all). Keeps the angles.
void frameSphere(ViewCamera& camera, const glm::dvec3& centre, double radius, double aspect);
// Looks through a camera placed by a world matrix: position and direction are kept exactly
// (roll is dropped: the viewport camera keeps +Y up); the orbit distance stays.
void setFromWorld(ViewCamera& camera, const glm::mat4& worldFromCamera, float yfov);

// A camera-path key at `time` from the current view (position, orientation, fov).
CameraKey keyFromView(const ViewCamera& camera, double time);

// The primary ray through pixel (px, py) (pixel centres at +0.5, y down) of a width x height view.
bvh::Ray pixelRay(const ViewCamera& camera, double px, double py, int width, int height);
// Where a world point lands in the view (pixels, y down); z < 0 when it is behind the camera.
glm::dvec3 projectToPixels(const ViewCamera& camera, const glm::dvec3& world, int width, int height);
// Near and far planes (x, y) for raster views of a scene inside `bounds`: far just beyond its
// farthest corner from the camera, near a fixed fraction of that (depth precision); an empty box:
// 0.01 and 1000 m, or more when the camera orbits farther out.
glm::dvec2 depthRange(const ViewCamera& camera, const bvh::Aabb& bounds);
// OpenGL clip-from-world for raster views and overlays; depth: near and far planes.
glm::mat4 clipFromWorld(const ViewCamera& camera, double aspect, glm::dvec2 depth = {0.01, 1000.0});

} // namespace glint::editor
