#pragma once
// The project file <basename>.glint.json: what glTF has no place for (docs/FILE_FORMAT.md).
#include "scene/core/diagnostics.h"
#include "scene/core/settings.h"

#include <filesystem>
#include <string>

namespace glint {

inline constexpr int kProjectSchemaVersion = 1;

// Render values a project may hold (the command line's ranges; docs/FILE_FORMAT.md).
inline constexpr int kMaxProjectImageSize = 16384;
inline constexpr int kMaxProjectSpp = 1048576;
inline constexpr int kMaxProjectBounces = 1024;
inline constexpr float kMaxProjectExposureEv = 64.0f;
// |anisotropy| of the fog: the Henyey-Greenstein lobe turns into a delta at 1, which the renderer's
// sampling cannot take (the glTF scatter extension keeps the same bound).
inline constexpr float kMaxFogAnisotropy = 0.99f;

struct ProjectFile {
    std::string sceneFile; // the glTF it belongs to, relative to the project file's folder
    ProjectSettings settings;
};

// <basename>.glint.json for a scene file ("a/b.gltf" -> "a/b.glint.json").
std::filesystem::path projectPathFor(const std::filesystem::path& sceneFile);
bool isProjectPath(const std::filesystem::path& file);

// Parses and migrates; throws FileError for malformed JSON, wrong types, values out of range or a
// newer schema.
ProjectFile parseProjectFile(const std::string& text, const std::string& displayName, Warnings& warnings);
// parseProjectFile, plus the folder check of its paths: an environment image outside the project's
// folder is FileError "uri-escapes-folder" naming the file and the key.
ProjectFile readProjectFile(const std::filesystem::path& file, Warnings& warnings);

// The environment image `file` (the project's `environment.file`) inside `projectFolder`, checked
// again whenever it is about to be opened (a symlink may have changed since the load). Throws
// FileError(displayName, "uri-escapes-folder", ...) when it leads out of the folder.
std::filesystem::path projectEnvironmentPath(const std::filesystem::path& projectFolder, const std::string& file,
                                             const std::string& displayName);

// Deterministic text (sorted keys, shortest round-trip numbers, locale-independent, trailing newline).
std::string writeProjectFileText(const ProjectFile& project);

} // namespace glint
