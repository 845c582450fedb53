#pragma once
// Sampling one glTF animation channel at a time t (seconds), following the glTF 2.0 spec:
// STEP holds the previous key; LINEAR lerps vectors and slerps rotations along the shortest arc;
// CUBICSPLINE is the Hermite spline with (in-tangent, value, out-tangent) per key, the tangents
// scaled by the key interval; rotations are normalised afterwards. Before the first key the first
// value holds, after the last key the last one.
#include "scene/core/animation.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace glint {

// Where t falls among the keys: the keys before and after it and the fraction between them.
// Outside the key range both keys are the clamped end key and fraction is 0.
struct KeyInterval {
    std::size_t before = 0;
    std::size_t after = 0;
    double fraction = 0.0; // in [0, 1)
    double duration = 0.0; // times[after] - times[before]
};
KeyInterval findKeyInterval(const std::vector<float>& times, double t);

// Translation or scale channel. A channel without keys is a logic error.
glm::vec3 sampleVec3Channel(const AnimationChannel& channel, double t);
// Rotation channel, (x, y, z, w) packed; the result has unit length.
glm::quat sampleRotationChannel(const AnimationChannel& channel, double t);

// True when the channel is a TRS channel with finite, strictly increasing key times and exactly the
// values its interpolation needs. Sampling needs at least keys; the rest keeps results meaningful.
bool isWellFormed(const AnimationChannel& channel);

} // namespace glint
