#pragma once
// Opens any scene file the CLI accepts: glTF and project files natively, other formats through the
// isolated importer. Throws FileError naming the file and the problem.
#include "scene/io/scene_io.h"

#include <filesystem>

namespace glint::cli {

bool isNativeSceneFile(const std::filesystem::path& file);
LoadResult openSceneFile(const std::filesystem::path& file);

} // namespace glint::cli
