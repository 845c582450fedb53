#pragma once
// Camera paths: position is a cubic Hermite curve in time with Catmull-Rom-style tangents from
// neighbouring keys (non-uniform in time), exact at keys and C1 in time; orientation by squad or
// slerp; optional constant-speed reparameterisation by arc length. Everything here is pure.
#include "scene/core/animation.h"
#include "scene/core/camera_path.h"
#include "scene/core/ids.h"

namespace glint {

// The camera state at time t (clamped to the first/last key). An empty path is a logic error.
CameraKey sampleCameraPath(const CameraPath& path, double t);

// Arc length of the position curve between the first and the last key, in metres.
double cameraPathLength(const CameraPath& path);

// A LINEAR glTF animation on `cameraNode` sampled at `fps` from the first to the last key (the last
// key always included), so other tools play the same motion. Marked bakedCameraPath.
Animation bakeCameraPath(const CameraPath& path, NodeId cameraNode, double fps);

} // namespace glint
