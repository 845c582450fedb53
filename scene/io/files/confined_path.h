#pragma once
// The folder check (docs/CLI.md, "Scene files"): a path inside a scene file may not leave the scene's folder
// (no `..` out of it, no absolute paths, no symlink pointing outside). One checker for every path a
// scene names: glTF URIs (confined_fs.h hands it to tinygltf) and the project file's environment
// image (checked at load and again by the renderer before it opens the file).
#include <filesystem>
#include <optional>
#include <string>

namespace glint {

struct ConfinedFolder {
    std::filesystem::path root; // the scene's folder
};

// Why `relative` may not be read from `folder` (a message naming the path), or nothing if it may.
// Symlinks are resolved before the check, so a link that leads out of the folder is refused too.
std::optional<std::string> confinementProblem(const ConfinedFolder& folder, const std::string& relative);

// The path `relative` names inside `folder`, or FileError(file, "uri-escapes-folder") if it leaves it.
std::filesystem::path confinedPath(const ConfinedFolder& folder, const std::string& relative, const std::string& file);

} // namespace glint
