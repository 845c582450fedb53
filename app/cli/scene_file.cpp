#include "scene_file.h"

#include "scene/import/import.h"
#include "scene/io/project/project_file.h"

#include <algorithm>
#include <cctype>

namespace glint::cli {

namespace {
std::string lowerExtension(const std::filesystem::path& file) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}
} // namespace

bool isNativeSceneFile(const std::filesystem::path& file) {
    std::string ext = lowerExtension(file);
    return ext == ".gltf" || ext == ".glb" || isProjectPath(file);
}

LoadResult openSceneFile(const std::filesystem::path& file) {
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) throw FileError(file.string(), "not-found", "no such file");
    if (std::filesystem::is_directory(file, ec)) throw FileError(file.string(), "is-directory", "is a folder, not a scene file");
    if (isNativeSceneFile(file)) return loadScene(file);
    return importScene(file, ImportOptions{});
}

} // namespace glint::cli
