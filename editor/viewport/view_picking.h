#pragma once
// What the viewport picks with, kept current without building on the GUI thread: the picker comes
// from the GPU scene's preparation on its worker (ScenePreparer, which reuses the mesh BVHs it
// builds anyway), or, where no preparation runs (the raster views, after a failed preparation), from
// a picker-only job on a worker of its own. After edits that leave the meshes as they are
// (transforms, lights, materials, time) the current picker is retargeted at once, on the GUI thread:
// a top-level rebuild, cheap. After edits that change them (geometry, hierarchy, visibility, another
// file) the old picker could name a wrong node, so picking reports nothing until the new one
// arrives. The same rules as the preparation: a newer job supersedes the one in flight, whose result
// is dropped; the destructor waits for the job in flight.
#include "editor/document/latest_job.h"
#include "editor/viewport/node_icons.h"
#include "editor/viewport/scene_picker.h"
#include "scene/history/change_set.h"

#include <QObject>

#include <cstdint>
#include <memory>
#include <vector>

namespace glint::editor {

class ViewPicking : public QObject {
    Q_OBJECT
public:
    explicit ViewPicking(QObject* parent = nullptr);
    ~ViewPicking() override;

    void noteChange(const ChangeSet& changes);
    void noteTime();
    void noteNewFile();
    // A GPU preparation of the document as it is now started: it will bring a picker.
    void preparationStarted();
    // Its picker (built on the worker), handed over when the preparation is uploaded.
    void adoptPrepared(std::shared_ptr<ScenePicker> picker);

    // The picker of `document` at `seconds`, or an empty one (picks nothing) while the current one
    // is on its way. `preparationComing`: a GPU preparation runs or is about to start, which will
    // bring it; otherwise a picker-only job starts.
    const ScenePicker& picker(const Scene& document, double seconds, bool preparationComing);
    bool current() const { return picker_ && pickerMeshes_ == meshes_; }
    int builtHere() const { return builtHere_; } // pickers built by picker-only jobs (tests)
    // The lights' and cameras' icons of `document` at `seconds`.
    const std::vector<NodeIcon>& icons(const Scene& document, double seconds);

signals:
    void arrived(); // a new picker is current: overlays drawn from it may change

private:
    void startJob(const Scene& document, double seconds);

    std::uint64_t meshes_ = 1; // bumped by changes to the meshes a picker holds
    std::uint64_t poses_ = 1;  // bumped by every change that may move something
    std::shared_ptr<ScenePicker> picker_;
    std::uint64_t pickerMeshes_ = 0, pickerPoses_ = 0;
    std::uint64_t preparedMeshes_ = 0, preparedPoses_ = 0; // of the GPU preparation in flight
    std::vector<NodeIcon> icons_;
    std::uint64_t iconPoses_ = 0;
    ScenePicker empty_;
    std::uint64_t jobMeshes_ = 0; // of the picker-only job in flight
    int builtHere_ = 0;
    LatestJob<std::shared_ptr<ScenePicker>> job_{this, 1}; // picker-only jobs
};

} // namespace glint::editor
