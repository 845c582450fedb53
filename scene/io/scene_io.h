#pragma once
// The public face of Glint's file I/O: load a scene (glTF + its project file), save it atomically.
// Implemented by gltf_read/, gltf_write/, project/ and files/atomic_save.cpp.
#include "scene/core/diagnostics.h"
#include "scene/core/scene.h"

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace glint {

class ImageDecoder; // image_decoder.h

struct LoadOptions {
    const ImageDecoder* images = nullptr; // null: images are kept as bytes, sizes from headers only
    std::uint64_t maxImagePixels = 16384ull * 16384ull;
    std::uint64_t maxBufferBytes = 2ull << 30; // refuse larger declared buffers
    int maxJsonDepth = 64;
    bool loadProjectFile = true;          // <basename>.glint.json beside the glTF, when present
};

struct LoadResult {
    Scene scene;
    Warnings warnings;
};

// FILE may be .gltf, .glb or a project file (.glint.json) that names its glTF.
// Throws FileError naming the file and the problem; never crashes on bad input.
LoadResult loadScene(const std::filesystem::path& file, const LoadOptions& options = {});

// Parse glTF/GLB bytes already in memory. `baseDir` resolves relative URIs (and confines them);
// `displayName` names the source in errors and warnings.
LoadResult loadGltfFromMemory(std::span<const std::uint8_t> bytes, const std::filesystem::path& baseDir,
                              const std::string& displayName, const LoadOptions& options = {});

struct SaveOptions {
    bool writeProjectFile = true;
    // The folder the scene's own relative paths resolve in now (the project's environment image):
    // the folder of the file it was loaded from or last saved to. Empty: the folder saved to (a save
    // in place). Saving into another folder copies the environment image there, as it does textures.
    std::filesystem::path sourceFolder;
};

struct SaveReport {
    Warnings dropped; // everything the save could not keep, each named
    std::vector<std::filesystem::path> written; // in the order they were renamed into place
};

// Saves FILE (.gltf or .glb) and its project file as one atomic set: every file is written to a
// temporary name and flushed, then renamed (buffers and images, the glTF, the project file), then the
// folder is synced. Deterministic: the same scene gives the same bytes. Throws FileError.
SaveReport saveScene(const Scene& scene, const std::filesystem::path& file, const SaveOptions& options = {});

// The same scene as one GLB in memory (no project file), for pipes, hashing and tests.
std::vector<std::uint8_t> writeGlb(const Scene& scene, SaveReport* report = nullptr);

} // namespace glint
