#include "camera_path_sampling.h"

#include "camera_path_arc_length.h"
#include "camera_path_hermite.h"
#include "camera_path_rotation.h"

#include <algorithm>
#include <optional>
#include <stdexcept>

namespace glint {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Hermite lens values can overshoot between keys; keep them physically meaningful.
void clampLens(CameraKey& key) {
    key.yfov = std::clamp(key.yfov, 1e-4f, float(kPi) - 1e-4f);
    key.focusDistance = std::max(key.focusDistance, 1e-4f);
    key.lensRadius = std::max(key.lensRadius, 0.0f);
}

// What every sample of one path (of at least two keys) shares, computed once.
struct PreparedPath {
    const CameraPath& path;
    std::vector<glm::dquat> orientations;
    std::optional<ArcLengthTable> arcLength; // constant speed only

    explicit PreparedPath(const CameraPath& p) : path(p), orientations(consistentOrientations(p.keys)) {
        if (p.constantSpeed) arcLength.emplace(p.keys);
    }

    // Constant speed: the curve time whose travelled distance is the same fraction of the whole
    // length as t is of the whole duration. A path that does not move keeps its own timing.
    double curveTime(double t) const {
        if (!arcLength || arcLength->totalLength() <= 0.0) return t;
        const double start = path.keys.front().time, end = path.keys.back().time;
        const double fraction = std::clamp((t - start) / (end - start), 0.0, 1.0);
        return arcLength->timeAtDistance(fraction * arcLength->totalLength());
    }
};

CameraKey interpolateKeys(const PreparedPath& prepared, double t) {
    const std::vector<CameraKey>& keys = prepared.path.keys;
    const PathSegment segment = findPathSegment(keys, t);
    CameraKey key;
    key.time = t;
    key.position = hermiteValue(keys, segment, [](const CameraKey& k) { return k.position; });
    key.orientation = interpolateOrientation(keys, prepared.orientations, segment, prepared.path.rotation);
    key.yfov = float(hermiteValue(keys, segment, [](const CameraKey& k) { return double(k.yfov); }));
    key.focusDistance = float(hermiteValue(keys, segment, [](const CameraKey& k) { return double(k.focusDistance); }));
    key.lensRadius = float(hermiteValue(keys, segment, [](const CameraKey& k) { return double(k.lensRadius); }));
    clampLens(key);
    return key;
}

} // namespace

std::vector<CameraKey> sampleCameraPath(const CameraPath& path, const std::vector<double>& times) {
    if (path.keys.empty()) throw std::logic_error("sampleCameraPath: the path has no keys");
    const std::vector<CameraKey>& keys = path.keys;
    std::optional<PreparedPath> prepared;
    if (keys.size() > 1) prepared.emplace(path);
    std::vector<CameraKey> samples;
    samples.reserve(times.size());
    for (double t : times) {
        const double clamped = std::clamp(t, keys.front().time, keys.back().time);
        samples.push_back(prepared ? interpolateKeys(*prepared, prepared->curveTime(clamped)) : keys.front());
        samples.back().time = clamped;
    }
    return samples;
}

CameraKey sampleCameraPath(const CameraPath& path, double t) {
    return sampleCameraPath(path, std::vector<double>{t}).front();
}

double cameraPathLength(const CameraPath& path) {
    if (path.keys.size() < 2) return 0.0;
    return ArcLengthTable(path.keys).totalLength();
}

} // namespace glint
