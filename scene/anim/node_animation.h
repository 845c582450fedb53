#pragma once
// Sampling glTF node animations (TRS; STEP, LINEAR, CUBICSPLINE) at any time.
#include "scene/core/animation.h"
#include "scene/core/scene.h"
#include "scene/core/transform.h"

#include <map>
#include <utility>

namespace glint {

// [start, end] of the keys of one animation, in seconds ({0, 0} when it has none).
std::pair<double, double> animationTimeSpan(const Animation& animation);
// The union over every animation of the scene, baked camera paths included.
std::pair<double, double> sceneAnimationTimeSpan(const Scene& scene);

// The local transform of `node` at time t with every animation of the scene applied to it
// (channels not targeting the node leave its stored TRS in place). Outside a channel's keys the
// first/last key holds. Pure: the scene is not changed.
Transform sampleLocalTransform(const Scene& scene, NodeId node, double t);

// All animated nodes at time t: node -> local transform. Use with Scene::setLocal on a copy.
std::map<NodeId, Transform> sampleAnimatedTransforms(const Scene& scene, double t);

} // namespace glint
