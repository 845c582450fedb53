#pragma once
// Keyframes of a node's transform, edited as an animator does it: "key" writes the node's local
// translation, rotation and scale at a time into the node's own animation (a glTF animation with
// one channel per path), replacing a key at the same time; keys move and go away together on all
// three paths. glTF keeps one interpolation per channel, so a node's track has one interpolation
// (step, linear, or cubic with automatic Catmull-Rom tangents, recomputed on every edit). Pure
// functions on values: the editor wraps them in undoable commands (SetAsset<Animation>).
#include "scene/core/scene.h"

#include <optional>
#include <vector>

namespace glint {

// The animation that holds `node`'s transform keys: the first (by id) with a channel on the node
// that is not a baked camera path; none when there is no such animation.
std::optional<AnimationId> nodeKeyAnimation(const Scene& scene, NodeId node);

// The node's key times (every path's, merged, ascending, seconds).
std::vector<double> nodeKeyTimes(const Animation& animation, NodeId node);
// The interpolation of the node's track (its first channel's); Linear when it has none.
Interpolation nodeKeyInterpolation(const Animation& animation, NodeId node);

// `animation` with the node keyed at `t` from `local` (channels made as needed, in `interpolation`).
Animation withNodeKey(Animation animation, NodeId node, double t, const Transform& local, Interpolation interpolation);
// Without the node's keys at `t` (within 1e-6 s); channels left without keys are removed.
Animation withoutNodeKey(Animation animation, NodeId node, double t);
// The node's keys at `from` moved to `to` (a key already at `to` is replaced).
Animation withNodeKeyMoved(Animation animation, NodeId node, double from, double to);
// Every channel of the node in `interpolation` (values and tangents rebuilt from the keys).
Animation withNodeInterpolation(Animation animation, NodeId node, Interpolation interpolation);

} // namespace glint
