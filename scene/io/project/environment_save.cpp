#include "environment_save.h"

#include "scene/io/files/confined_path.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <system_error>

namespace glint {

namespace fs = std::filesystem;

namespace {

// An HDR is tens of megabytes at most; the limit only keeps a wrong path from reading a disk image.
constexpr std::uintmax_t kMaxEnvironmentBytes = 2ull << 30;

std::optional<std::vector<std::uint8_t>> readBytes(const fs::path& file)
{
    std::error_code error;
    if (!fs::is_regular_file(file, error) || fs::file_size(file, error) > kMaxEnvironmentBytes || error) return std::nullopt;
    std::ifstream in(file, std::ios::binary);
    if (!in) return std::nullopt;
    return std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

bool sameFile(const fs::path& a, const fs::path& b)
{
    std::error_code error;
    return fs::equivalent(a, b, error) && !error;
}

bool isTaken(const EnvironmentSaveContext& context, const fs::path& relative)
{
    const fs::path normal = relative.lexically_normal();
    return std::any_of(context.taken.begin(), context.taken.end(),
                       [&](const fs::path& taken) { return taken.lexically_normal() == normal; });
}

} // namespace

EnvironmentSave saveEnvironment(const Environment& environment, const EnvironmentSaveContext& context, Warnings& dropped)
{
    const std::string& file = environment.file;
    if (file.empty()) return {};
    const auto drop = [&](const std::string& code, const std::string& message) {
        dropped.push_back({context.displayName, code, "environment image '" + file + "' " + message});
    };
    // A path inside the source folder keeps its relative path, as textures do. One outside it (a
    // file the user picked in the editor) is copied into the folder under its own name: the loader
    // refuses paths that leave the scene's folder, so the saved project could not be opened.
    const bool inside = !confinementProblem(ConfinedFolder{context.sourceFolder}, file);
    const fs::path target = inside ? fs::path(file) : fs::path(file).filename();
    // The editor wrote an outside path with QDir::relativeFilePath, which is lexical: read it so.
    const fs::path source = inside ? context.sourceFolder / file : (context.sourceFolder / file).lexically_normal();
    if (sameFile(source, context.targetFolder / target)) return {target.generic_string(), std::nullopt};

    std::optional<std::vector<std::uint8_t>> bytes = readBytes(source);
    if (!bytes) {
        if (!inside) {
            drop("environment-dropped", "is outside the scene's folder and cannot be read: left out of the project file");
            return {};
        }
        // Kept as it is, so a file put there later is used. Saved into another folder, the report
        // says that it did not come along; in place nothing changes, so there is nothing to name.
        if (!sameFile(context.sourceFolder, context.targetFolder))
            drop("environment-not-copied", "cannot be read from '" + context.sourceFolder.string() + "': not copied beside the saved scene");
        return {file, std::nullopt};
    }
    if (target.empty() || isTaken(context, target)) {
        drop("environment-dropped", "has the name of a file the save writes: left out of the project file");
        return {};
    }
    if (!inside) {
        // Never replace a different file of the same name that is already in the folder.
        std::optional<std::vector<std::uint8_t>> existing = readBytes(context.targetFolder / target);
        if (existing && *existing != *bytes) {
            drop("environment-dropped", "is outside the scene's folder and '" + target.generic_string() +
                                            "' there holds another file: left out of the project file");
            return {};
        }
    }
    return {target.generic_string(), PendingFile{context.targetFolder / target, std::move(*bytes)}};
}

} // namespace glint
