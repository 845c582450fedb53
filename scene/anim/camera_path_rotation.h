#pragma once
// Orientation along a camera path.
//  - Slerp: each segment is a shortest-arc slerp between its keys: exact at keys, C0 (the angular
//    velocity jumps at keys).
//  - Squad (default): Shoemake's spherical quadrangle with inner control rotations chosen for
//    non-uniform key times, so the angular velocity at key k is the central difference
//    log(q[k-1]^-1 q[k+1]) / (t[k+1] - t[k-1]) from both sides: exact at keys and C1 in time
//    (away from degenerate cases: neighbouring keys 180 degrees apart). The end keys use
//    themselves as control rotations, so a two-key path is a plain slerp.
#include "camera_path_hermite.h"

#include <glm/gtc/quaternion.hpp>

namespace glint {

// Keys' orientations made hemisphere-consistent (each within 90 degrees of the one before), so
// interpolation never takes the long way round.
std::vector<glm::dquat> consistentOrientations(const std::vector<CameraKey>& keys);

glm::dquat interpolateOrientation(const std::vector<CameraKey>& keys, const std::vector<glm::dquat>& orientations,
                                  const PathSegment& segment, RotationInterpolation mode);

} // namespace glint
