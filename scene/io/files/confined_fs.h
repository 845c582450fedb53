#pragma once
// tinygltf's file-system callbacks confined to the scene's folder (the check is confined_path.h).
#include "confined_path.h"

#include <tiny_gltf.h>

namespace glint {

// tinygltf callbacks that read only inside `folder` (which must outlive the loader) and never write.
tinygltf::FsCallbacks confinedFsCallbacks(ConfinedFolder* folder);

} // namespace glint
