#pragma once
// Import of OBJ, PLY, STL, FBX, DAE and 3DS through Assimp. Assimp is not hardened against
// hostile files, so it runs in a child process (glint-import-worker): a crash, a hang or a runaway
// allocation there becomes a FileError here and never takes the caller down.
//
// The worker converts Assimp's scene to a glint::Scene (metres, +Y up, metallic-roughness
// materials) and sends it back as GLB bytes, which are parsed with the glTF reader.
#include "scene/io/scene_io.h"

#include <atomic>
#include <chrono>
#include <cstdint>
#include <filesystem>

namespace glint {

struct ImportOptions {
    // Empty: findImportWorker() (next to the running executable, then ../libexec/glint/).
    std::filesystem::path workerPath;
    std::chrono::milliseconds timeout{120'000};
    std::uint64_t maxFileBytes = 1ull << 30;          // larger input files are refused unread
    std::uint64_t maxResultBytes = 2ull << 30;        // the worker's reply, read with this cap
    std::uint64_t maxWorkerMemoryBytes = 8ull << 30;  // the worker's address space; 0 = no limit
    std::uint64_t maxTriangles = 64'000'000;          // over the whole converted scene
    LoadOptions load;                                 // for parsing the worker's GLB
    // Set from another thread to stop the import: the worker is killed at once (within ~50 ms)
    // and importScene throws FileError "import-cancelled".
    const std::atomic<bool>* cancel = nullptr;
};

// The lower-case extensions importScene accepts: ".obj", ".ply", ".stl", ".fbx", ".dae", ".3ds".
bool isImportableFile(const std::filesystem::path& file);

// Imports FILE in a child process. Throws FileError naming the file: "not-found", "empty-file",
// "too-large", "unsupported-format", "import-failed" (Assimp's message), "importer-crashed",
// "importer-timeout", "importer-failed" (bad exit or reply), "worker-not-found", "import-cancelled".
LoadResult importScene(const std::filesystem::path& file, const ImportOptions& options = {});

// Where the worker executable is looked for when ImportOptions::workerPath is empty. Empty when
// it is in neither place.
std::filesystem::path findImportWorker();

} // namespace glint
