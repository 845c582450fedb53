#pragma once
// The cubic Hermite scheme camera paths use for positions and lens values: exact at keys, C1 in
// time, with tangents from the neighbouring keys that respect non-uniform key spacing.
#include "scene/core/camera_path.h"

#include <cstddef>
#include <vector>

namespace glint {

// The segment [keys[index], keys[index + 1]] that holds t, and where t lies in it (u in [0, 1]).
// Times before the first key or after the last are clamped to it. Needs at least two keys.
struct PathSegment {
    std::size_t index = 0;
    double u = 0.0;
    double duration = 0.0;
};
PathSegment findPathSegment(const std::vector<CameraKey>& keys, double t);

// The tangent (derivative in time) at key k: the slope of the parabola through keys k-1, k, k+1,
// i.e. the two neighbouring secant slopes weighted by the opposite interval (non-uniform
// Catmull-Rom). At the first and last key the one-sided secant slope.
template <class Get>
auto hermiteTangent(const std::vector<CameraKey>& keys, std::size_t k, Get get) {
    const std::size_t last = keys.size() - 1;
    auto slope = [&](std::size_t a) { return (get(keys[a + 1]) - get(keys[a])) / (keys[a + 1].time - keys[a].time); };
    if (k == 0) return slope(0);
    if (k == last) return slope(last - 1);
    const double before = keys[k].time - keys[k - 1].time;
    const double after = keys[k + 1].time - keys[k].time;
    return (slope(k - 1) * after + slope(k) * before) / (before + after);
}

// The Hermite curve through the keys at the segment position s.
template <class Get>
auto hermiteValue(const std::vector<CameraKey>& keys, const PathSegment& s, Get get) {
    const double u = s.u, u2 = u * u, u3 = u2 * u;
    const std::size_t i = s.index;
    return (2 * u3 - 3 * u2 + 1) * get(keys[i]) + (u3 - 2 * u2 + u) * s.duration * hermiteTangent(keys, i, get)
         + (-2 * u3 + 3 * u2) * get(keys[i + 1]) + (u3 - u2) * s.duration * hermiteTangent(keys, i + 1, get);
}

// Its derivative in time.
template <class Get>
auto hermiteDerivative(const std::vector<CameraKey>& keys, const PathSegment& s, Get get) {
    const double u = s.u, u2 = u * u;
    const std::size_t i = s.index;
    const auto perU = (6 * u2 - 6 * u) * get(keys[i]) + (3 * u2 - 4 * u + 1) * s.duration * hermiteTangent(keys, i, get)
                    + (-6 * u2 + 6 * u) * get(keys[i + 1]) + (3 * u2 - 2 * u) * s.duration * hermiteTangent(keys, i + 1, get);
    return perU / s.duration;
}

} // namespace glint
