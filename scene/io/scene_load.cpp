// loadScene: a .gltf, a .glb, or a project file (.glint.json) that names its glTF.
#include "scene/io/files/confined_path.h"
#include "scene/io/project/project_file.h"
#include "scene/io/scene_io.h"

#include <fstream>
#include <iterator>
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

// The project file beside a glTF, when there is one.
void addProjectSettings(LoadResult& result, const fs::path& sceneFile)
{
    const fs::path project = projectPathFor(sceneFile);
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
