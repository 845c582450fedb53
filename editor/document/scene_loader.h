#pragma once
// Reads a scene file on a worker thread, so the editor's event loop never waits for a glTF parse
// or an Assimp import. One load is current at a time (LatestJob, as the viewport's ScenePreparer):
// start() supersedes it and cancel() drops it, and only the current load's finished() or failed()
// is ever emitted, on the GUI thread.
//
// Cancelling an import kills its child process at once (ImportOptions::cancel). A glTF parse has
// no way to stop half-way: a cancelled one runs on to its end on its worker and its result is
// dropped, while the next load starts on another worker at once. The destructor cancels and waits,
// so nothing outlives the loader (at most the rest of one glTF parse).
#include "editor/document/latest_job.h"
#include "scene/import/import.h"
#include "scene/io/scene_io.h"

#include <QObject>
#include <QString>

#include <memory>

namespace glint::editor {

// Whether Glint opens PATH itself (.gltf, .glb, .glint.json) rather than importing it.
bool isNativeScene(const QString& path);

// The whole read, on whatever thread calls it: a native scene through the glTF reader, anything
// else through the import child process. Throws FileError naming the file.
LoadResult readSceneFile(const QString& path, const ImportOptions& importOptions);

class SceneLoader : public QObject {
    Q_OBJECT
public:
    explicit SceneLoader(QObject* parent = nullptr);
    ~SceneLoader() override;

    // Options for imports (the worker executable, limits); their cancel flag is the loader's own.
    void setImportOptions(ImportOptions options);

    // Reads `path` on a worker, cancelling the load in flight.
    void start(const QString& path);
    // Drops the load in flight: its result never arrives; an import's child is killed.
    void cancel();
    bool busy() const { return job_.busy(); }
    // Workers still reading, cancelled reads included (a glTF parse ends on its own).
    int runningReads() const { return job_.running(); }
    // The result of the last finished(), handed over once.
    std::unique_ptr<LoadResult> take() { return std::move(ready_); }

signals:
    void progress(const QString& stage); // for people: what the worker is doing now
    void finished();
    void failed(const QString& message);

private:
    ImportOptions importOptions_;
    std::unique_ptr<LoadResult> ready_;
    // A cancelled glTF parse keeps its worker until it ends: the next load takes another one.
    LatestJob<std::shared_ptr<LoadResult>> job_{this, 3};
};

} // namespace glint::editor
