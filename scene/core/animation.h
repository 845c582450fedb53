#pragma once
#include "ids.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace glint {

enum class Interpolation { Step, Linear, CubicSpline };
enum class AnimationPath { Translation, Rotation, Scale, Weights };

// One glTF animation channel with its sampler folded in. Values are packed floats:
// 3 per key for translation/scale, 4 (x, y, z, w) for rotation; CUBICSPLINE stores
// (in-tangent, value, out-tangent) per key as glTF does.
struct AnimationChannel {
    NodeId node{};
    AnimationPath path = AnimationPath::Translation;
    Interpolation interpolation = Interpolation::Linear;
    std::vector<float> times;
    std::vector<float> values;
    friend bool operator==(const AnimationChannel&, const AnimationChannel&) = default;
};

struct Animation {
    std::string name;
    std::vector<AnimationChannel> channels;
    bool bakedCameraPath = false; // generated from a camera path on save; regenerated, not edited
    nlohmann::json unknown;
    friend bool operator==(const Animation&, const Animation&) = default;
};

} // namespace glint
