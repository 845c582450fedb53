// loadScene: a .gltf, a .glb, or a project file (.glint.json) that names its glTF.
#include "scene/io/files/atomic_save.h"
#include "scene/io/files/confined_path.h"
#include "scene/io/project/project_file.h"
#include "scene/io/scene_io.h"

#include <fstream>
#include <iterator>
#include <optional>
#include <variant>

namespace glint {

namespace fs = std::filesystem;

namespace {

std::vector<std::uint8_t> readFileBytes(const fs::path& file, std::uint64_t limit)
{
    std::error_code error;
    const auto size = fs::file_size(file, error);
    if (error) throw FileError(file.string(), "missing-file", "cannot read the file: " + error.message());
    if (size > limit) throw FileError(file.string(), "buffer-too-large", "the file has " + std::to_string(size) + " bytes, more than the limit");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw FileError(file.string(), "missing-file", "cannot open the file");
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

LoadResult loadGltfFile(const fs::path& file, const LoadOptions& options)
{
    const std::vector<std::uint8_t> bytes = readFileBytes(file, options.maxBufferBytes);
    const fs::path folder = file.parent_path().empty() ? fs::path(".") : file.parent_path();
    return loadGltfFromMemory(bytes, folder, file.string(), options);
}

// The project's active camera must be a camera node of the glTF it belongs to: a dangling id would
// render through some other camera without a word.
void checkActiveCamera(const Scene& scene, const fs::path& project)
{
    const NodeId id = scene.settings.activeCamera;
    if (!id.valid()) return;
    const Node* node = scene.node(id);
    if (!node || !std::holds_alternative<Camera>(node->component))
        throw FileError(project.string(), "bad-value",
                        "key 'activeCamera' must be the id of a camera node of the scene: " + std::to_string(id.value) +
                            (node ? " is not a camera" : " names no node"));
}

// A save killed after its glTF was renamed into place and before its project file was
// (atomic_save.h, after stage 2) leaves that project file whole under its temporary name: every
// temporary is written and synced before the first rename. It belongs to the glTF on disk when the
// glTF's own temporary is gone (its rename happened) and it is not older than the glTF, so it is
// read instead of the previous save's project file; the next save puts it in place.
std::optional<fs::path> interruptedProjectFile(const fs::path& sceneFile, const fs::path& project)
{
    std::error_code error;
    const fs::file_time_type sceneTime = fs::last_write_time(sceneFile, error);
    if (error) return std::nullopt;
    std::optional<fs::path> found;
    fs::file_time_type newest{};
    const fs::path folder = sceneFile.parent_path().empty() ? fs::path(".") : sceneFile.parent_path();
    for (const auto& entry : fs::directory_iterator(folder, error)) {
        const std::string final = finalNameOfTemporary(entry.path());
        if (final == sceneFile.filename().string()) return std::nullopt; // the glTF's save did not finish
        if (final != project.filename().string()) continue;
        const fs::file_time_type time = entry.last_write_time(error);
        if (!error && time >= sceneTime && (!found || time > newest)) {
            found = entry.path();
            newest = time;
        }
    }
    return found;
}

// The project file beside a glTF, when there is one.
void addProjectSettings(LoadResult& result, const fs::path& sceneFile)
{
    fs::path project = projectPathFor(sceneFile);
    if (const std::optional<fs::path> interrupted = interruptedProjectFile(sceneFile, project)) {
        result.warnings.push_back({project.string(), "project-save-interrupted",
                                   "the last save stopped before its project file was in place: read from " +
                                       interrupted->filename().string() + " (the next save puts it in place)"});
        project = *interrupted;
    }
    std::error_code error;
    if (!fs::exists(project, error)) return;
    result.scene.settings = readProjectFile(project, result.warnings).settings;
    checkActiveCamera(result.scene, project);
}

} // namespace

LoadResult loadScene(const fs::path& file, const LoadOptions& options)
{
    if (isProjectPath(file)) {
        Warnings warnings;
        ProjectFile project = readProjectFile(file, warnings);
        const ConfinedFolder folder{file.parent_path().empty() ? fs::path(".") : file.parent_path()};
        LoadResult result = loadGltfFile(confinedPath(folder, project.sceneFile, file.string()), options);
        result.scene.settings = std::move(project.settings);
        checkActiveCamera(result.scene, file);
        warnings.insert(warnings.end(), result.warnings.begin(), result.warnings.end());
        result.warnings = std::move(warnings);
        return result;
    }
    const std::string ext = file.extension().string();
    if (ext != ".gltf" && ext != ".glb")
        throw FileError(file.string(), "unsupported-format", "can only load .gltf, .glb or .glint.json (not '" + ext + "')");
    LoadResult result = loadGltfFile(file, options);
    if (options.loadProjectFile) addProjectSettings(result, file);
    return result;
}

} // namespace glint
