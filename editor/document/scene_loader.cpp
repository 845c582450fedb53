#include "scene_loader.h"

#include <filesystem>
#include <utility>

namespace glint::editor {
namespace {

std::filesystem::path toPath(const QString& path) { return std::filesystem::path(path.toStdString()); }

} // namespace

bool isNativeScene(const QString& path) {
    const QString lower = path.toLower();
    return lower.endsWith(".gltf") || lower.endsWith(".glb") || lower.endsWith(".glint.json");
}

LoadResult readSceneFile(const QString& path, const ImportOptions& importOptions) {
    if (isNativeScene(path)) return loadScene(toPath(path));
    if (isImportableFile(toPath(path))) return importScene(toPath(path), importOptions);
    throw FileError(path.toStdString(), "unsupported-format", "not a scene file Glint can open or import");
}

SceneLoader::SceneLoader(QObject* parent) : QObject(parent) {}

SceneLoader::~SceneLoader() = default; // job_ cancels (an import's child is killed) and waits

void SceneLoader::setImportOptions(ImportOptions options) { importOptions_ = std::move(options); }

// On a worker: no Qt object is touched but through queued calls (LatestJob::post).
void SceneLoader::start(const QString& path) {
    ready_.reset();
    auto work = [this, path, options = importOptions_](const Ticket& ticket) {
        const QString stage = isNativeScene(path) ? tr("reading the glTF file") : tr("running the importer");
        job_.post(ticket, [this, stage] { emit progress(stage); });
        ImportOptions importOptions = options;
        importOptions.cancel = &ticket->cancelled; // the ticket outlives the import that reads it
        return std::make_shared<LoadResult>(readSceneFile(path, importOptions));
    };
    job_.start(
        std::move(work),
        [this](std::shared_ptr<LoadResult> result) {
            ready_ = std::make_unique<LoadResult>(std::move(*result));
            emit finished();
        },
        [this](const QString& message) { emit failed(message); });
}

void SceneLoader::cancel() {
    job_.cancel();
    ready_.reset();
}

} // namespace glint::editor
