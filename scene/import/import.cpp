#include "import.h"

#include "child_process.h"
#include "worker_reply.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstring>
#include <string>
#include <system_error>

namespace glint {

namespace {

constexpr std::array kImportable{".obj", ".ply", ".stl", ".fbx", ".dae", ".3ds"};

std::string lowerExtension(const std::filesystem::path& file) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

// The checks that need no child process: they give the most specific messages.
void checkInputFile(const std::filesystem::path& file, const ImportOptions& options) {
    const std::string name = file.string();
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) throw FileError(name, "not-found", "no such file");
    if (!std::filesystem::is_regular_file(file, ec)) throw FileError(name, "not-a-file", "is not a regular file");
    if (!isImportableFile(file))
        throw FileError(name, "unsupported-format",
                        "unsupported file type '" + file.extension().string() + "' (import reads .obj, .ply, .stl, .fbx, .dae, .3ds)");
    const auto size = std::filesystem::file_size(file, ec);
    if (ec) throw FileError(name, "unreadable", "cannot read: " + ec.message());
    if (size == 0) throw FileError(name, "empty-file", "the file is empty");
    if (size > options.maxFileBytes)
        throw FileError(name, "too-large", "the file is " + std::to_string(size) + " bytes, more than the import limit of " +
                                               std::to_string(options.maxFileBytes));
}

std::vector<std::string> workerCommand(const std::filesystem::path& worker, const std::filesystem::path& file,
                                       const ImportOptions& options) {
    return {worker.string(),
            "--max-memory", std::to_string(options.maxWorkerMemoryBytes),
            "--max-triangles", std::to_string(options.maxTriangles),
            std::filesystem::absolute(file).lexically_normal().string()};
}

// A child that did not hand back a reply: say what happened to it, in words a user can act on.
[[noreturn]] void throwForOutcome(const std::string& name, const ChildOutcome& outcome, const ImportOptions& options) {
    using Kind = ChildOutcome::Kind;
    switch (outcome.kind) {
    case Kind::Signalled:
        throw FileError(name, "importer-crashed", "importer crashed (signal " + std::to_string(outcome.code) + ")");
    case Kind::TimedOut:
        throw FileError(name, "importer-timeout", "importer timed out after " + std::to_string(options.timeout.count()) + " ms");
    case Kind::OutputTooLarge:
        throw FileError(name, "importer-failed", "importer result is larger than " + std::to_string(options.maxResultBytes) + " bytes");
    case Kind::Cancelled:
        throw FileError(name, "import-cancelled", "import cancelled");
    case Kind::SpawnFailed:
        throw FileError(name, "worker-not-found", std::string("cannot start the importer: ") + std::strerror(outcome.code));
    case Kind::Exited:
        break;
    }
    throw FileError(name, "importer-failed",
                    "importer failed (exit status " + std::to_string(outcome.code) + ", no readable result)");
}

std::filesystem::path resolveWorker(const std::string& name, const ImportOptions& options) {
    std::filesystem::path worker = options.workerPath.empty() ? findImportWorker() : options.workerPath;
    if (worker.empty())
        throw FileError(name, "worker-not-found", "cannot find glint-import-worker next to this program or in ../libexec/glint/");
    return worker;
}

} // namespace

bool isImportableFile(const std::filesystem::path& file) {
    const std::string ext = lowerExtension(file);
    return std::find(kImportable.begin(), kImportable.end(), ext) != kImportable.end();
}

LoadResult importScene(const std::filesystem::path& file, const ImportOptions& options) {
    const std::string name = file.string();
    checkInputFile(file, options);
    const std::filesystem::path worker = resolveWorker(name, options);

    ChildOutcome outcome = runChild(workerCommand(worker, file, options), {options.timeout, options.maxResultBytes, options.cancel});
    std::optional<WorkerReply> reply;
    if (outcome.kind == ChildOutcome::Kind::Exited) reply = decodeWorkerReply(outcome.output);
    if (!reply) throwForOutcome(name, outcome, options);
    if (!reply->errorCode.empty()) throw FileError(name, reply->errorCode, reply->errorMessage);

    LoadOptions load = options.load;
    load.loadProjectFile = false;
    LoadResult result = loadGltfFromMemory(reply->glb, file.parent_path(), name, load);
    // The transfer GLB carries bytes for every image the importer could read; the rest it named
    // already (missing, refused, unreadable), so reading their bare URIs again says it twice.
    std::erase_if(result.warnings, [](const Warning& w) { return w.code == "missing-texture"; });
    for (Warning& w : reply->warnings) w.file = name;
    result.warnings.insert(result.warnings.begin(), reply->warnings.begin(), reply->warnings.end());
    return result;
}

} // namespace glint
