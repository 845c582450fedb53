#include "camera_path_rotation.h"

#include <cmath>

namespace glint {

namespace {

// Unit-quaternion logarithm: axis * half-angle.
glm::dvec3 logUnit(const glm::dquat& q) {
    const glm::dvec3 v{q.x, q.y, q.z};
    const double sinHalf = glm::length(v);
    if (sinHalf < 1e-12) return glm::dvec3(0.0);
    return v * (std::atan2(sinHalf, q.w) / sinHalf);
}

glm::dquat expPure(const glm::dvec3& v) {
    const double halfAngle = glm::length(v);
    if (halfAngle < 1e-12) return glm::dquat(1.0, v.x, v.y, v.z);
    const glm::dvec3 axisSin = v * (std::sin(halfAngle) / halfAngle);
    return glm::dquat(std::cos(halfAngle), axisSin.x, axisSin.y, axisSin.z);
}

// slerp(a, b, u) = a * exp(u * log(a^-1 b)); written out so both squad levels use one definition.
glm::dquat slerpUnit(const glm::dquat& a, const glm::dquat& b, double u) {
    return glm::normalize(a * expPure(u * logUnit(glm::inverse(a) * b)));
}

// The inner control rotation at key k. Squad's derivative at the start of segment k is
// q_k (a + 2c) / dt_k and at the end of segment k-1 it is q_k (-b - 2c) / dt_{k-1}, with
// a = log(q_k^-1 q_{k+1}), b = log(q_k^-1 q_{k-1}) and c = log(q_k^-1 s_k); equating them gives c.
glm::dquat controlRotation(const std::vector<CameraKey>& keys, const std::vector<glm::dquat>& q, std::size_t k) {
    if (k == 0 || k + 1 == q.size()) return q[k];
    const glm::dquat inverse = glm::inverse(q[k]);
    const glm::dvec3 a = logUnit(inverse * q[k + 1]);
    const glm::dvec3 b = logUnit(inverse * q[k - 1]);
    const double before = keys[k].time - keys[k - 1].time;
    const double after = keys[k + 1].time - keys[k].time;
    const glm::dvec3 c = -(before * a + after * b) / (2.0 * (before + after));
    return glm::normalize(q[k] * expPure(c));
}

} // namespace

std::vector<glm::dquat> consistentOrientations(const std::vector<CameraKey>& keys) {
    std::vector<glm::dquat> result;
    result.reserve(keys.size());
    for (const CameraKey& key : keys) {
        glm::dquat q = glm::normalize(key.orientation);
        if (!result.empty() && glm::dot(result.back(), q) < 0.0) q = -q;
        result.push_back(q);
    }
    return result;
}

glm::dquat interpolateOrientation(const std::vector<CameraKey>& keys, const std::vector<glm::dquat>& q,
                                  const PathSegment& s, RotationInterpolation mode) {
    const std::size_t i = s.index;
    const glm::dquat along = slerpUnit(q[i], q[i + 1], s.u);
    if (mode == RotationInterpolation::Slerp) return along;
    const glm::dquat controls = slerpUnit(controlRotation(keys, q, i), controlRotation(keys, q, i + 1), s.u);
    return slerpUnit(along, controls, 2.0 * s.u * (1.0 - s.u));
}

} // namespace glint
