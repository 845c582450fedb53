#pragma once
// The scene as it is at time t: node animations applied and every camera placed on its camera path.
// Renders of animations and `glint render --time` use this on a copy of the document.
#include "scene/core/scene.h"

namespace glint {

// Poses `scene` in place at time t (seconds). Camera paths are in world space: a camera node with a
// parent gets the local transform that puts it on the path. Lens settings (yfov, focus distance,
// lens radius) follow the path too.
void poseSceneAt(Scene& scene, double t);

// A posed copy; the document itself is never changed by time.
Scene sceneAt(const Scene& scene, double t);

// Whether node animations or a camera path move anything over time.
bool sceneAnimates(const Scene& scene);

// `scene` itself where nothing animates, else its posed copy at t held in `storage`: a pose without
// copying the meshes of a still scene.
const Scene& posedAt(const Scene& scene, double t, Scene& storage);

} // namespace glint
