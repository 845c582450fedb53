// saveScene and writeGlb: the glTF writer's output plus the project file, saved as one atomic set.
#include "scene_io.h"

#include "scene/io/files/atomic_save.h"
#include "scene/io/gltf_write/gltf_writer.h"
#include "scene/io/project/environment_save.h"
#include "scene/io/project/project_file.h"

#include <algorithm>
#include <system_error>
#include <variant>

namespace glint {

namespace {

std::string lowercaseExtension(const std::filesystem::path& file)
{
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

std::vector<std::uint8_t> bytesOf(const std::string& text) { return {text.begin(), text.end()}; }

// <basename>.<16 hex digits>.bin: buffers an earlier save of this scene wrote.
bool isOwnBufferName(const std::string& name, const std::string& baseName)
{
    const std::string prefix = baseName + ".";
    if (name.size() != prefix.size() + 16 + 4 || name.rfind(prefix, 0) != 0 || !name.ends_with(".bin")) return false;
    return std::all_of(name.begin() + static_cast<std::ptrdiff_t>(prefix.size()), name.end() - 4,
                       [](char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); });
}

// Runs after the new set is in place and synced, so a crash before it only leaves an unused file.
// Also removes temporaries of buffers an interrupted save was writing (their names differ from
// this save's, so the atomic save's own clean-up does not see them).
void removeOldBuffers(const std::filesystem::path& folder, const std::string& baseName, const std::string& current)
{
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
        const std::string name = entry.path().filename().string();
        const bool oldBuffer = name != current && isOwnBufferName(name, baseName);
        if (oldBuffer || isOwnBufferName(finalNameOfTemporary(entry.path()), baseName)) std::filesystem::remove(entry.path(), ec);
    }
}

// The project as saved: its environment image copied beside the new file (added to `data`), and
// nothing the loader would refuse (an active camera that is no camera node is left out), so every
// saved scene opens again.
ProjectSettings settingsForSave(const Scene& scene, const std::string& displayName, const std::filesystem::path& folder,
                                const SaveOptions& options, std::vector<PendingFile>& data, Warnings& dropped)
{
    ProjectSettings settings = scene.settings;
    if (!options.writeProjectFile) return settings;
    EnvironmentSaveContext context{options.sourceFolder.empty() ? folder : std::filesystem::absolute(options.sourceFolder),
                                   folder, {}, displayName};
    const std::filesystem::path project = projectPathFor(std::filesystem::path(displayName)).filename();
    context.taken = {std::filesystem::path(displayName).filename(), project};
    for (const PendingFile& file : data) context.taken.push_back(file.path.lexically_relative(folder));
    EnvironmentSave environment = saveEnvironment(settings.environment, context, dropped);
    settings.environment.file = environment.file;
    if (environment.copy) data.push_back(std::move(*environment.copy));

    const NodeId camera = settings.activeCamera;
    const Node* node = camera.valid() ? scene.node(camera) : nullptr;
    if (camera.valid() && (!node || !std::holds_alternative<Camera>(node->component))) {
        dropped.push_back({displayName, "active-camera-dropped",
                           "the active camera " + std::to_string(camera.value) + " is not a camera node: left out of the project file"});
        settings.activeCamera = {};
    }
    return settings;
}

} // namespace

std::vector<std::uint8_t> writeGlb(const Scene& scene, SaveReport* report)
{
    GltfOutput output = writeGltf(scene, {GltfContainer::Binary, "scene", "scene.glb", {}});
    if (report) report->dropped = output.dropped;
    return glbBytes(output);
}

SaveReport saveScene(const Scene& scene, const std::filesystem::path& file, const SaveOptions& options)
{
    const std::string ext = lowercaseExtension(file);
    if (ext != ".gltf" && ext != ".glb")
        throw FileError(file.string(), "unsupported-format", "can only save .gltf or .glb (not '" + ext + "')");
    const std::filesystem::path target = std::filesystem::absolute(file);
    const std::filesystem::path folder = target.parent_path();
    const std::filesystem::path project = projectPathFor(target);

    GltfWriteOptions writeOptions;
    writeOptions.container = ext == ".glb" ? GltfContainer::Binary : GltfContainer::Text;
    writeOptions.baseName = target.stem().string();
    writeOptions.displayName = file.string();
    writeOptions.reservedUris = {target.filename().string(), project.filename().string()};
    GltfOutput output = writeGltf(scene, writeOptions);

    std::vector<PendingFile> data;
    if (!output.binUri.empty()) data.push_back({folder / output.binUri, output.bin});
    for (ExternalFile& image : output.images) data.push_back({folder / image.path, std::move(image.bytes)});
    Warnings dropped = std::move(output.dropped);
    const ProjectSettings settings = settingsForSave(scene, file.string(), folder, options, data, dropped);
    std::vector<std::vector<PendingFile>> stages{std::move(data)};
    const bool binary = writeOptions.container == GltfContainer::Binary;
    stages.push_back({{target, binary ? glbBytes(output) : bytesOf(output.json)}});
    if (options.writeProjectFile)
        stages.push_back({{project, bytesOf(writeProjectFileText({target.filename().string(), settings}))}});

    SaveReport report;
    report.written = saveFilesAtomically(stages);
    report.dropped = std::move(dropped);
    if (!binary) removeOldBuffers(folder, writeOptions.baseName, output.binUri);
    return report;
}

} // namespace glint
