#include "camera_path_sampling.h"

#include <algorithm>
#include <cmath>

namespace glint {

namespace {

bool isFinite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool isUsable(const CameraKey& key) {
    const glm::dquat& q = key.orientation;
    const double norm = glm::length(q);
    return std::isfinite(key.time) && isFinite(key.position) && std::isfinite(norm) && norm > 0.0
        && std::isfinite(key.yfov) && std::isfinite(key.focusDistance) && std::isfinite(key.lensRadius);
}

} // namespace

bool isValidCameraPath(const CameraPath& path) {
    const auto& keys = path.keys;
    const auto notAfter = [](const CameraKey& a, const CameraKey& b) { return b.time <= a.time; };
    return !keys.empty() && std::all_of(keys.begin(), keys.end(), isUsable)
        && std::adjacent_find(keys.begin(), keys.end(), notAfter) == keys.end();
}

} // namespace glint
