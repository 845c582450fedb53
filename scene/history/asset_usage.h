#pragma once
// Whether anything in the scene still refers to an asset. Removing an asset in use would leave
// dangling ids, so RemoveAsset refuses it: remove or re-point the users first (in one macro).
#include "scene/core/scene.h"

namespace glint {

bool isInUse(const Scene& scene, MeshId mesh);         // mesh instances
bool isInUse(const Scene& scene, MaterialId material); // shapes and mesh primitives
bool isInUse(const Scene& scene, TextureId texture);   // material texture slots
bool isInUse(const Scene& scene, ImageId image);       // textures
bool isInUse(const Scene& scene, SamplerId sampler);   // textures
inline bool isInUse(const Scene&, AnimationId) { return false; } // nothing refers to an animation

} // namespace glint
