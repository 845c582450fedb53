#pragma once
// The project file <basename>.glint.json: what glTF has no place for (docs/FILE_FORMAT.md).
#include "scene/core/diagnostics.h"
#include "scene/core/settings.h"

#include <filesystem>
#include <string>

namespace glint {

inline constexpr int kProjectSchemaVersion = 1;

struct ProjectFile {
    std::string sceneFile; // the glTF it belongs to, relative to the project file's folder
    ProjectSettings settings;
};

// <basename>.glint.json for a scene file ("a/b.gltf" -> "a/b.glint.json").
std::filesystem::path projectPathFor(const std::filesystem::path& sceneFile);
bool isProjectPath(const std::filesystem::path& file);

// Parses and migrates; throws FileError for malformed JSON, wrong types or a newer schema.
ProjectFile parseProjectFile(const std::string& text, const std::string& displayName, Warnings& warnings);
ProjectFile readProjectFile(const std::filesystem::path& file, Warnings& warnings);

// Deterministic text (sorted keys, shortest round-trip numbers, locale-independent, trailing newline).
std::string writeProjectFileText(const ProjectFile& project);

} // namespace glint
