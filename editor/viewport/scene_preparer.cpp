#include "editor/viewport/scene_preparer.h"

#include "scene/anim/scene_at_time.h"

#include <QElapsedTimer>

#include <utility>
#include <vector>

namespace glint::editor {

std::shared_ptr<ScenePicker> pickerFromPreparation(const Scene& posed, const renderer::MeshData& meshes) {
    std::vector<bvh::Aabb> roots;
    roots.reserve(meshes.bvhs.size());
    for (const bvh::MeshBvh& mesh : meshes.bvhs) roots.push_back(mesh.bounds());
    return std::make_shared<ScenePicker>(posed, std::move(roots), meshes.ids, meshes.flat);
}

ScenePreparer::ScenePreparer(QObject* parent)
    : QObject(parent), meshCache_(std::make_shared<renderer::MeshBvhCache>()),
      textureCache_(std::make_shared<renderer::TextureCache>()) {}

ScenePreparer::~ScenePreparer() = default; // job_ cancels and waits: the worker stops at its next step

void ScenePreparer::start(Scene document, double seconds, std::filesystem::path environmentFile, renderer::TextureLimits limits) {
    ready_.reset();
    ++generation_;
    auto input = std::make_shared<Scene>(std::move(document)); // moved into the result on the worker
    // On the worker: CPU work only; progress comes back through queued calls.
    auto work = [this, input, seconds, environmentFile = std::move(environmentFile), limits](const Ticket& ticket) {
        QElapsedTimer clock;
        clock.start();
        renderer::PrepareControl control;
        control.progress = [this, ticket](renderer::PreparationStage stage, std::size_t done, std::size_t total) {
            if (ticket->cancelled) throw renderer::PreparationCancelled{};
            job_.post(ticket, [this, stage, done, total] { emit progress(stage, int(done), int(total)); });
        };
        Scene storage;
        const Scene& posed = posedAt(*input, seconds, storage); // the document itself when nothing animates
        auto result = std::make_shared<PreparedDocument>();
        result->gpu = renderer::prepareScene(posed, environmentFile, limits, *meshCache_, control, textureCache_.get());
        control.progress(renderer::PreparationStage::Picking, 0, 1); // may stop here too
        result->picker = pickerFromPreparation(posed, result->gpu.meshes);
        result->document = std::move(*input);
        result->time = seconds;
        result->milliseconds = double(clock.nsecsElapsed()) / 1e6;
        return result;
    };
    job_.start(
        std::move(work),
        [this](std::shared_ptr<PreparedDocument> result) {
            ready_ = std::make_unique<PreparedDocument>(std::move(*result));
            emit finished();
        },
        [this](const QString& message) { emit failed(message); });
}

void ScenePreparer::cancel() {
    job_.cancel();
    ready_.reset(); // a result not yet uploaded is superseded too: another file must never show it
}

std::unique_ptr<PreparedDocument> ScenePreparer::take() { return std::move(ready_); }

} // namespace glint::editor
