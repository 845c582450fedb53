#pragma once
// Runs the CPU stage of the GPU scene (renderer::prepareScene: mesh BVHs, top level, texture
// decoding and mipmaps, packing) on a worker thread, so the viewport's event loop never waits for
// it; the GL upload stays with the viewport, on the GL thread (no GL here, no context on the worker).
// The click picker is built there too, from the same mesh BVHs (they are not built twice).
//
// One preparation runs at a time, on one worker, so the mesh BVH cache the worker keeps across
// preparations is never shared. start() supersedes (LatestJob): the preparation in flight is
// cancelled at its next step (between two meshes or two textures) and its result never arrives;
// only the newest one's finished() or failed() is emitted. The destructor cancels and waits for the
// worker (at most one step), so closing the document or the application leaves nothing running.
#include "editor/document/latest_job.h"
#include "editor/viewport/scene_picker.h"
#include "renderer/gpu_scene/prepared_scene.h"

#include <QObject>
#include <QString>

#include <cstdint>
#include <filesystem>
#include <memory>

namespace glint::editor {

// A finished preparation: the document it was made from (not yet posed) and the GPU scene's CPU data.
struct PreparedDocument {
    Scene document;
    double time = 0.0;
    renderer::PreparedScene gpu;
    std::shared_ptr<ScenePicker> picker; // of the posed scene, over gpu's mesh BVHs
    double milliseconds = 0.0; // on the worker
};

// The click picker of a posed scene over the mesh BVHs a preparation built for it (a copy of their
// flattened nodes and triangles: the GPU scene keeps its own).
std::shared_ptr<ScenePicker> pickerFromPreparation(const Scene& posed, const renderer::MeshData& meshes);

class ScenePreparer : public QObject {
    Q_OBJECT
public:
    explicit ScenePreparer(QObject* parent = nullptr);
    ~ScenePreparer() override;

    // Prepares `document` posed at `seconds`, cancelling the preparation in flight.
    void start(Scene document, double seconds, std::filesystem::path environmentFile, renderer::TextureLimits limits);
    // Cancels the preparation in flight and drops a finished result not yet taken.
    void cancel();
    bool busy() const { return job_.busy(); }
    bool hasResult() const { return ready_ != nullptr; } // finished, not yet taken
    std::uint64_t started() const { return generation_; } // preparations started so far
    // The result of the last finished(), handed over once.
    std::unique_ptr<PreparedDocument> take();

signals:
    // `done` of `total` steps of `stage`.
    void progress(renderer::PreparationStage stage, int done, int total);
    void finished();
    void failed(const QString& message);

private:
    std::shared_ptr<renderer::MeshBvhCache> meshCache_;
    std::shared_ptr<renderer::TextureCache> textureCache_; // decoded images: a rebuild decodes only new image bytes
    std::unique_ptr<PreparedDocument> ready_;
    std::uint64_t generation_ = 0;
    LatestJob<std::shared_ptr<PreparedDocument>> job_{this, 1}; // one thread: preparations run one after another
};

} // namespace glint::editor
