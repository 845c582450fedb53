#pragma once
// Camera paths: position is a cubic Hermite curve in time with Catmull-Rom-style tangents from
// neighbouring keys (non-uniform in time), exact at keys and C1 in time; orientation by squad or
// slerp; optional constant-speed reparameterisation by arc length. Everything here is pure.
//
// Position: non-uniform Catmull-Rom tangents (the slope of the parabola through each key and its
// neighbours; one-sided secant slopes at the ends), see camera_path_hermite.h.
// Orientation: RotationInterpolation::Squad (the default) is C1 in time with tangents adapted to
// non-uniform key times; Slerp is C0 (angular velocity jumps at keys). See camera_path_rotation.h.
// yfov, focus distance and lens radius: the same Hermite scheme as position (C1), clamped to valid
// ranges (yfov in (0, pi), focus > 0, lens radius >= 0) where a spline would overshoot.
// constantSpeed: the time t is first mapped to the curve time whose travelled distance is the same
// fraction of the whole length as t is of the whole duration; everything (orientation and lens
// values too) is then sampled at that curve time, so the camera moves at constant speed and passes
// each key's position with that key's orientation, though not at the key's own time.
#include "scene/core/animation.h"
#include "scene/core/camera_path.h"
#include "scene/core/ids.h"

#include <vector>

namespace glint {

// What sampling needs: at least one key, finite times strictly increasing, finite positions and
// lens values, non-zero finite orientations. Loaders and commands check this.
bool isValidCameraPath(const CameraPath& path);

// The camera state at time t (clamped to the first/last key; the result's time is the clamped t).
// An empty path is a logic error (std::logic_error).
CameraKey sampleCameraPath(const CameraPath& path, double t);

// The same at many times at once, sharing the per-path set-up (the arc-length table of the
// constant-speed mode): use this for animations.
std::vector<CameraKey> sampleCameraPath(const CameraPath& path, const std::vector<double>& times);

// Arc length of the position curve between the first and the last key, in metres.
double cameraPathLength(const CameraPath& path);

// A LINEAR glTF animation on `cameraNode` sampled at `fps` from the first to the last key (the last
// key always included), so other tools play the same motion. Marked bakedCameraPath. The values are
// the path's own (world) position and orientation, i.e. the node's local TRS when the camera node
// is a root. Throws std::invalid_argument for fps <= 0, std::length_error past 1e7 samples.
Animation bakeCameraPath(const CameraPath& path, NodeId cameraNode, double fps);

} // namespace glint
