#include "scene_loader.h"

#include <QMetaObject>

#include <atomic>
#include <exception>
#include <filesystem>

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

struct SceneLoader::Job {
    QString path;
    ImportOptions importOptions;
    std::atomic<bool> cancelled{false};
    // Written by the worker before it posts deliver(), read on the GUI thread after.
    std::unique_ptr<LoadResult> result;
    QString error;
};

SceneLoader::SceneLoader(QObject* parent) : QObject(parent) {
    // A cancelled glTF parse keeps its worker until it ends: the next load takes another one.
    pool_.setMaxThreadCount(3);
}

SceneLoader::~SceneLoader() {
    cancel();
    pool_.waitForDone();
}

void SceneLoader::setImportOptions(ImportOptions options) { importOptions_ = std::move(options); }

void SceneLoader::start(const QString& path) {
    cancel();
    auto job = std::make_shared<Job>();
    job->path = path;
    job->importOptions = importOptions_;
    job->importOptions.cancel = &job->cancelled; // the job outlives the import that reads it
    current_ = job;
    pool_.start([this, job] { run(job); });
}

void SceneLoader::cancel() {
    if (current_) current_->cancelled = true;
    current_.reset();
    ready_.reset();
}

// On a worker: no Qt object is touched but through queued calls to this one, which outlives the
// worker (the destructor waits).
void SceneLoader::run(const std::shared_ptr<Job>& job) {
    if (job->cancelled) return; // superseded while it waited for a worker
    const QString stage = isNativeScene(job->path) ? tr("reading the glTF file") : tr("running the importer");
    QMetaObject::invokeMethod(this, [this, job, stage] {
        if (job == current_) emit progress(stage);
    }, Qt::QueuedConnection);
    try {
        job->result = std::make_unique<LoadResult>(readSceneFile(job->path, job->importOptions));
    } catch (const std::exception& e) {
        job->error = QString::fromStdString(e.what());
    }
    if (job->cancelled) return; // its result is dropped here, on the worker
    QMetaObject::invokeMethod(this, [this, job] { deliver(job); }, Qt::QueuedConnection);
}

void SceneLoader::deliver(const std::shared_ptr<Job>& job) {
    if (job != current_) return; // superseded after it finished
    current_.reset();
    if (!job->result) {
        emit failed(job->error);
        return;
    }
    ready_ = std::move(job->result);
    emit finished();
}

} // namespace glint::editor
