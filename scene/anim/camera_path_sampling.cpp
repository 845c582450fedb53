#include "camera_path_sampling.h"

#include "camera_path_arc_length.h"
#include "camera_path_hermite.h"
#include "camera_path_rotation.h"

#include <algorithm>
#include <stdexcept>

namespace glint {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Constant speed: the path time whose travelled distance is the same fraction of the whole
// length as t is of the whole duration. A path that does not move keeps its own timing.
double constantSpeedTime(const std::vector<CameraKey>& keys, double t) {
    const ArcLengthTable table(keys);
    if (table.totalLength() <= 0.0) return t;
    const double start = keys.front().time, end = keys.back().time;
    const double fraction = std::clamp((t - start) / (end - start), 0.0, 1.0);
    return table.timeAtDistance(fraction * table.totalLength());
}

// Hermite lens values can overshoot between keys; keep them physically meaningful.
void clampLens(CameraKey& key) {
    key.yfov = std::clamp(key.yfov, 1e-4f, float(kPi) - 1e-4f);
    key.focusDistance = std::max(key.focusDistance, 1e-4f);
    key.lensRadius = std::max(key.lensRadius, 0.0f);
}

CameraKey interpolateKeys(const std::vector<CameraKey>& keys, RotationInterpolation rotation, double t) {
    const PathSegment segment = findPathSegment(keys, t);
    CameraKey key;
    key.time = t;
    key.position = hermiteValue(keys, segment, [](const CameraKey& k) { return k.position; });
    key.orientation = interpolateOrientation(keys, consistentOrientations(keys), segment, rotation);
    key.yfov = float(hermiteValue(keys, segment, [](const CameraKey& k) { return double(k.yfov); }));
    key.focusDistance = float(hermiteValue(keys, segment, [](const CameraKey& k) { return double(k.focusDistance); }));
    key.lensRadius = float(hermiteValue(keys, segment, [](const CameraKey& k) { return double(k.lensRadius); }));
    clampLens(key);
    return key;
}

} // namespace

CameraKey sampleCameraPath(const CameraPath& path, double t) {
    if (path.keys.empty()) throw std::logic_error("sampleCameraPath: the path has no keys");
    const std::vector<CameraKey>& keys = path.keys;
    const double clamped = std::clamp(t, keys.front().time, keys.back().time);
    if (keys.size() == 1) {
        CameraKey only = keys.front();
        only.time = clamped;
        return only;
    }
    const double curveTime = path.constantSpeed ? constantSpeedTime(keys, clamped) : clamped;
    CameraKey key = interpolateKeys(keys, path.rotation, curveTime);
    key.time = clamped;
    return key;
}

double cameraPathLength(const CameraPath& path) {
    if (path.keys.size() < 2) return 0.0;
    return ArcLengthTable(path.keys).totalLength();
}

} // namespace glint
