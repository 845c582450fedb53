#pragma once
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <vector>

namespace glint {

// One key of a camera path. Times are seconds; orientation is cameraWorldFromLocal's rotation
// (the camera looks along its local -Z, as in glTF).
struct CameraKey {
    double time = 0.0;
    glm::dvec3 position{0.0};
    glm::dquat orientation{1.0, 0.0, 0.0, 0.0};
    float yfov = 0.6911112f;
    float focusDistance = 1.0f;
    float lensRadius = 0.0f;
    friend bool operator==(const CameraKey&, const CameraKey&) = default;
};

enum class RotationInterpolation { Slerp, Squad };

// Keys sorted by time, strictly increasing. Sampling lives in scene/anim (camera_path_sampling.h).
struct CameraPath {
    std::vector<CameraKey> keys;
    RotationInterpolation rotation = RotationInterpolation::Squad;
    bool constantSpeed = false;

    bool empty() const { return keys.empty(); }
    friend bool operator==(const CameraPath&, const CameraPath&) = default;
};

} // namespace glint
