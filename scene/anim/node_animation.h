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
// The union over every animation of the scene and every camera path (baked or not).
std::pair<double, double> sceneAnimationTimeSpan(const Scene& scene);

// The local transform of `node` at time t with every animation of the scene applied to it
// (channels not targeting the node leave its stored TRS in place). Outside a channel's keys the
// first/last key holds. Animations apply in id order, so a later channel on the same node and
// path wins. A camera node with a camera path follows the exact (world-space) path instead: the
// local transform that puts it there under its parent's stored world transform (for animated
// parents use sceneAt, scene_at_time.h); baked camera-path animations are ignored for it.
// Malformed channels (isWellFormed) are skipped.
// Pure: the scene is not changed. An unknown node throws std::out_of_range.
Transform sampleLocalTransform(const Scene& scene, NodeId node, double t);

// All animated nodes (camera-path nodes included) at time t: node -> local transform, as
// sampleLocalTransform gives it. Use with Scene::setLocal on a copy.
std::map<NodeId, Transform> sampleAnimatedTransforms(const Scene& scene, double t);

} // namespace glint
