#include "editor/viewport/view_camera.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace glint::editor {

namespace {

constexpr double kPitchLimit = 1.5533430342749532; // 89 degrees: the view never flips over the pole
constexpr double kMinDistance = 1e-3;

// Unit vector from the target to the camera.
glm::dvec3 backward(const ViewCamera& c) {
    return {std::cos(c.pitch) * std::sin(c.yaw), std::sin(c.pitch), std::cos(c.pitch) * std::cos(c.yaw)};
}

} // namespace

glm::dvec3 ViewCamera::position() const { return target + distance * backward(*this); }

glm::dquat ViewCamera::orientation() const {
    const glm::dquat yawQ = glm::angleAxis(yaw, glm::dvec3(0.0, 1.0, 0.0));
    const glm::dquat pitchQ = glm::angleAxis(-pitch, glm::dvec3(1.0, 0.0, 0.0));
    return yawQ * pitchQ;
}

glm::dvec3 ViewCamera::forward() const { return -backward(*this); }
glm::dvec3 ViewCamera::right() const { return orientation() * glm::dvec3(1.0, 0.0, 0.0); }
glm::dvec3 ViewCamera::up() const { return orientation() * glm::dvec3(0.0, 1.0, 0.0); }

glm::mat4 ViewCamera::worldFromCamera() const {
    glm::dmat4 m = glm::mat4_cast(orientation());
    m[3] = glm::dvec4(position(), 1.0);
    return glm::mat4(m);
}

void orbit(ViewCamera& camera, double dx, double dy, double radiansPerPixel) {
    camera.yaw -= dx * radiansPerPixel;
    camera.pitch = std::clamp(camera.pitch + dy * radiansPerPixel, -kPitchLimit, kPitchLimit);
}

void pan(ViewCamera& camera, double dx, double dy, int viewportHeight) {
    const double metresPerPixel = 2.0 * camera.distance * std::tan(0.5 * camera.yfov) / std::max(1, viewportHeight);
    camera.target += (-dx * camera.right() + dy * camera.up()) * metresPerPixel;
}

void zoom(ViewCamera& camera, double steps) {
    camera.distance = std::max(kMinDistance, camera.distance * std::pow(0.85, steps));
}

void look(ViewCamera& camera, double dx, double dy, double radiansPerPixel) {
    const glm::dvec3 eye = camera.position();
    camera.yaw -= dx * radiansPerPixel;
    camera.pitch = std::clamp(camera.pitch + dy * radiansPerPixel, -kPitchLimit, kPitchLimit);
    camera.target = eye - camera.distance * backward(camera);
}

void fly(ViewCamera& camera, const glm::dvec3& move) {
    camera.target += move.x * camera.right() + move.y * camera.up() + move.z * camera.forward();
}

void frameSphere(ViewCamera& camera, const glm::dvec3& centre, double radius, double aspect) {
    const double halfY = 0.5 * camera.yfov;
    const double halfX = std::atan(std::tan(halfY) * std::max(aspect, 1e-3));
    const double half = std::min(halfX, halfY);
    camera.target = centre;
    camera.distance = std::max(kMinDistance, 1.1 * std::max(radius, 1e-3) / std::sin(half));
}

void setFromWorld(ViewCamera& camera, const glm::mat4& worldFromCamera, float yfov) {
    const glm::dmat4 m(worldFromCamera);
    const glm::dvec3 eye(m[3]);
    const glm::dvec3 back = glm::normalize(glm::dvec3(m[2]));
    camera.yfov = yfov;
    camera.pitch = std::clamp(std::asin(std::clamp(back.y, -1.0, 1.0)), -kPitchLimit, kPitchLimit);
    camera.yaw = std::atan2(back.x, back.z);
    camera.target = eye - camera.distance * backward(camera);
}

CameraKey keyFromView(const ViewCamera& camera, double time) {
    CameraKey key;
    key.time = time;
    key.position = camera.position();
    key.orientation = camera.orientation();
    key.yfov = camera.yfov;
    key.focusDistance = static_cast<float>(camera.distance);
    return key;
}

bvh::Ray pixelRay(const ViewCamera& camera, double px, double py, int width, int height) {
    const double t = std::tan(0.5 * camera.yfov);
    const double aspect = double(width) / std::max(1, height);
    const double x = (2.0 * px / std::max(1, width) - 1.0) * t * aspect;
    const double y = (1.0 - 2.0 * py / std::max(1, height)) * t;
    const glm::dvec3 dir = camera.orientation() * glm::normalize(glm::dvec3(x, y, -1.0));
    return {glm::vec3(camera.position()), glm::vec3(dir)};
}

glm::dvec3 projectToPixels(const ViewCamera& camera, const glm::dvec3& world, int width, int height) {
    const glm::dvec3 local = glm::inverse(camera.orientation()) * (world - camera.position());
    const double depth = -local.z;
    const double t = std::tan(0.5 * camera.yfov);
    const double aspect = double(width) / std::max(1, height);
    const double safe = std::abs(depth) < 1e-12 ? 1e-12 : depth;
    const double x = local.x / (safe * t * aspect);
    const double y = local.y / (safe * t);
    return {(x + 1.0) * 0.5 * width, (1.0 - y) * 0.5 * height, depth};
}

glm::dvec2 depthRange(const ViewCamera& camera, const bvh::Aabb& bounds) {
    constexpr double kNearFraction = 1e-5; // of the far plane: 24-bit depth still separates surfaces
    double zFar = std::max(1000.0, 4.0 * camera.distance);
    if (!bounds.empty()) {
        const glm::dvec3 eye = camera.position();
        double farthest = 0.0;
        for (int corner = 0; corner < 8; ++corner) {
            const glm::dvec3 p((corner & 1) ? bounds.hi.x : bounds.lo.x, (corner & 2) ? bounds.hi.y : bounds.lo.y,
                               (corner & 4) ? bounds.hi.z : bounds.lo.z);
            farthest = std::max(farthest, glm::length(p - eye));
        }
        zFar = std::max(1.0, 1.01 * farthest);
    }
    return {std::max(1e-4, kNearFraction * zFar), zFar};
}

glm::mat4 clipFromWorld(const ViewCamera& camera, double aspect, glm::dvec2 depth) {
    const glm::dmat4 clipFromCamera = glm::perspective(double(camera.yfov), aspect, depth.x, depth.y);
    return glm::mat4(clipFromCamera * glm::inverse(glm::dmat4(camera.worldFromCamera())));
}

} // namespace glint::editor
