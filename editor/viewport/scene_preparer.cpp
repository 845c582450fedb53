#include "editor/viewport/scene_preparer.h"

#include <QElapsedTimer>
#include <QMetaObject>

#include <exception>
#include <utility>
#include <vector>

namespace glint::editor {

std::shared_ptr<ScenePicker> pickerFromPreparation(const Scene& posed, const renderer::MeshData& meshes) {
    std::vector<bvh::Aabb> roots;
    roots.reserve(meshes.bvhs.size());
    for (const bvh::MeshBvh& mesh : meshes.bvhs) roots.push_back(mesh.bounds());
    return std::make_shared<ScenePicker>(posed, std::move(roots), meshes.ids, meshes.flat);
}

struct ScenePreparer::Job {
    Scene document;
    double time = 0.0;
    std::filesystem::path environmentFile;
    renderer::TextureLimits limits;
    std::atomic<bool> cancelled{false};
    // Written by the worker before it posts deliver(), read on the GUI thread after.
    std::unique_ptr<PreparedDocument> result;
    QString error;
};

ScenePreparer::ScenePreparer(QObject* parent) : QObject(parent), meshCache_(std::make_shared<renderer::MeshBvhCache>()),
      textureCache_(std::make_shared<renderer::TextureCache>()) {
    pool_.setMaxThreadCount(1);
}

ScenePreparer::~ScenePreparer() {
    cancel();
    pool_.waitForDone(); // the worker stops at its next step; nothing outlives the preparer
}

void ScenePreparer::start(Scene document, double seconds, std::filesystem::path environmentFile, renderer::TextureLimits limits) {
    cancel();
    auto job = std::make_shared<Job>();
    job->document = std::move(document);
    job->time = seconds;
    job->environmentFile = std::move(environmentFile);
    job->limits = limits;
    current_ = job;
    ++generation_;
    pool_.start([this, job] { run(job); });
}

void ScenePreparer::cancel() {
    if (current_) current_->cancelled = true;
    current_.reset();
    ready_.reset(); // a result not yet uploaded is superseded too: another file must never show it
}

std::unique_ptr<PreparedDocument> ScenePreparer::take() { return std::move(ready_); }

// On the worker thread: CPU work only. Progress and the result go back through queued calls to
// this object, which Qt drops if the preparer is gone (it never is: the destructor waits).
void ScenePreparer::run(const std::shared_ptr<Job>& job) {
    if (job->cancelled) return; // superseded while it waited for the worker
    QElapsedTimer clock;
    clock.start();
    try {
        renderer::PrepareControl control;
        control.progress = [this, job](const char* stage, std::size_t done, std::size_t total) {
            if (job->cancelled) throw renderer::PreparationCancelled{};
            QMetaObject::invokeMethod(this, [this, job, name = QString::fromLatin1(stage), done, total] {
                if (job == current_) emit progress(name, int(done), int(total));
            }, Qt::QueuedConnection);
        };
        const Scene posed = renderer::sceneForTime(job->document, job->time);
        auto result = std::make_unique<PreparedDocument>();
        result->gpu = renderer::prepareScene(posed, job->environmentFile, job->limits, *meshCache_, control, textureCache_.get());
        control.progress("picking", 0, 1); // may stop here too
        result->picker = pickerFromPreparation(posed, result->gpu.meshes);
        result->document = std::move(job->document);
        result->time = job->time;
        result->milliseconds = double(clock.nsecsElapsed()) / 1e6;
        job->result = std::move(result);
    } catch (const renderer::PreparationCancelled&) {
        return;
    } catch (const std::exception& e) {
        job->error = QString::fromStdString(e.what());
    }
    QMetaObject::invokeMethod(this, [this, job] { deliver(job); }, Qt::QueuedConnection);
}

void ScenePreparer::deliver(const std::shared_ptr<Job>& job) {
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
