#pragma once
// The project's environment image on save: the glTF writer copies textures beside the new file,
// this does the same for the one file the project file names, so a scene saved into another folder
// still renders (docs/FILE_FORMAT.md, "Saving the environment image").
#include "scene/io/files/atomic_save.h"

#include "scene/core/diagnostics.h"
#include "scene/core/settings.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace glint {

struct EnvironmentSave {
    std::string file;                // what the saved project's `environment.file` says (empty: none)
    std::optional<PendingFile> copy; // the image to write beside the new file, when it must be copied
};

struct EnvironmentSaveContext {
    std::filesystem::path sourceFolder; // where `environment.file` resolves now (absolute)
    std::filesystem::path targetFolder; // the saved scene's folder (absolute)
    std::vector<std::filesystem::path> taken; // files this save writes, relative to targetFolder
    std::string displayName;            // the saved file, naming it in the report
};

// Decides where the environment image goes. What cannot be kept is named in `dropped`.
EnvironmentSave saveEnvironment(const Environment& environment, const EnvironmentSaveContext& context, Warnings& dropped);

} // namespace glint
