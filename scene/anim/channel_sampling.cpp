#include "channel_sampling.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace glint {

namespace {

std::size_t componentCount(AnimationPath path) { return path == AnimationPath::Rotation ? 4 : 3; }

// The i-th element of `width` floats; for CUBICSPLINE `slot` picks in-tangent (0), value (1) or
// out-tangent (2) of key i.
glm::vec4 element(const AnimationChannel& c, std::size_t key, int slot) {
    const std::size_t width = componentCount(c.path);
    const std::size_t perKey = c.interpolation == Interpolation::CubicSpline ? 3 : 1;
    const std::size_t slotIndex = c.interpolation == Interpolation::CubicSpline ? std::size_t(slot) : 0;
    const float* v = c.values.data() + (key * perKey + slotIndex) * width;
    return {v[0], v[1], v[2], width == 4 ? v[3] : 0.0f};
}

constexpr int kInTangent = 0;
constexpr int kValue = 1;
constexpr int kOutTangent = 2;

glm::vec4 hermite(const AnimationChannel& c, const KeyInterval& k) {
    const float u = float(k.fraction);
    const float u2 = u * u;
    const float u3 = u2 * u;
    const float dt = float(k.duration);
    return (2 * u3 - 3 * u2 + 1) * element(c, k.before, kValue)
         + (u3 - 2 * u2 + u) * dt * element(c, k.before, kOutTangent)
         + (-2 * u3 + 3 * u2) * element(c, k.after, kValue)
         + (u3 - u2) * dt * element(c, k.after, kInTangent);
}

glm::quat toQuat(const glm::vec4& xyzw) { return glm::quat(xyzw.w, xyzw.x, xyzw.y, xyzw.z); }

// Shortest-arc slerp: glTF quaternions q and -q are the same rotation.
glm::quat slerpShortest(glm::quat a, glm::quat b, float u) {
    if (glm::dot(a, b) < 0.0f) b = -b;
    return glm::normalize(glm::slerp(a, b, u));
}

glm::quat normalizedOrIdentity(const glm::quat& q) {
    const float len = glm::length(q);
    return len > 0.0f ? q / len : glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
}

} // namespace

KeyInterval findKeyInterval(const std::vector<float>& times, double t) {
    const std::size_t last = times.size() - 1;
    if (t <= times.front()) return {0, 0, 0.0, 0.0};
    if (t >= times[last]) return {last, last, 0.0, 0.0};
    const auto after = std::size_t(std::upper_bound(times.begin(), times.end(), t) - times.begin());
    const std::size_t before = after - 1;
    const double duration = double(times[after]) - double(times[before]);
    const double fraction = duration > 0.0 ? (t - double(times[before])) / duration : 0.0;
    return {before, after, fraction, duration};
}

bool isWellFormed(const AnimationChannel& c) {
    if (c.path == AnimationPath::Weights || c.times.empty()) return false;
    const bool increasing =
        std::adjacent_find(c.times.begin(), c.times.end(), std::greater_equal<>()) == c.times.end();
    if (!std::isfinite(c.times.front()) || !increasing) return false;
    const std::size_t perKey = c.interpolation == Interpolation::CubicSpline ? 3 : 1;
    return c.values.size() == c.times.size() * perKey * componentCount(c.path);
}

glm::vec3 sampleVec3Channel(const AnimationChannel& c, double t) {
    const KeyInterval k = findKeyInterval(c.times, t);
    if (k.before == k.after || c.interpolation == Interpolation::Step) return element(c, k.before, kValue);
    if (c.interpolation == Interpolation::Linear)
        return glm::mix(element(c, k.before, kValue), element(c, k.after, kValue), float(k.fraction));
    return hermite(c, k);
}

glm::quat sampleRotationChannel(const AnimationChannel& c, double t) {
    const KeyInterval k = findKeyInterval(c.times, t);
    const glm::quat before = toQuat(element(c, k.before, kValue));
    if (k.before == k.after || c.interpolation == Interpolation::Step) return normalizedOrIdentity(before);
    if (c.interpolation == Interpolation::Linear)
        return slerpShortest(normalizedOrIdentity(before), normalizedOrIdentity(toQuat(element(c, k.after, kValue))),
                             float(k.fraction));
    return normalizedOrIdentity(toQuat(hermite(c, k)));
}

} // namespace glint
