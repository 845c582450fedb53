#include "editor/viewport/view_picking.h"

#include "renderer/gpu_scene/prepared_scene.h"
#include "scene/anim/scene_at_time.h"

#include <utility>

namespace glint::editor {

namespace {

// Changes after which a picker's mesh part (which meshes, instanced where, visible or not) may be
// out of date. Transforms, lights, materials, cameras and names leave it as it is.
bool changesMeshes(const ChangeSet& changes) {
    return changes.has(Change::Geometry) || changes.has(Change::Structure) || changes.has(Change::Visibility);
}

} // namespace

ViewPicking::ViewPicking(QObject* parent) : QObject(parent) {}

ViewPicking::~ViewPicking() = default; // job_ waits for at most one picker build

void ViewPicking::noteChange(const ChangeSet& changes) {
    if (!affectsImage(changes) && !changes.has(Change::Visibility)) return;
    ++poses_;
    if (changesMeshes(changes)) ++meshes_;
}

void ViewPicking::noteTime() { ++poses_; }

void ViewPicking::noteNewFile() {
    ++poses_;
    ++meshes_;
    picker_.reset(); // the old file's picker is of no use
}

void ViewPicking::preparationStarted() {
    preparedMeshes_ = meshes_;
    preparedPoses_ = poses_;
}

void ViewPicking::adoptPrepared(std::shared_ptr<ScenePicker> picker) {
    if (!picker || preparedMeshes_ != meshes_) return; // the meshes changed since it started: a newer one comes
    picker_ = std::move(picker);
    pickerMeshes_ = preparedMeshes_;
    pickerPoses_ = preparedPoses_;
    job_.cancel(); // a picker-only job in flight is superseded
    emit arrived();
}

const ScenePicker& ViewPicking::picker(const Scene& document, double seconds, bool preparationComing) {
    if (current()) {
        if (pickerPoses_ != poses_) {
            Scene storage;
            picker_->retarget(posedAt(document, seconds, storage));
            pickerPoses_ = poses_;
        }
        return *picker_;
    }
    if (!preparationComing && !(job_.busy() && jobMeshes_ == meshes_)) startJob(document, seconds);
    return empty_;
}

void ViewPicking::startJob(const Scene& document, double seconds) {
    // The worker's own copy, posed.
    auto posed = std::make_shared<Scene>(sceneAnimates(document) ? sceneAt(document, seconds) : document);
    const std::uint64_t meshes = meshes_, poses = poses_;
    jobMeshes_ = meshes;
    job_.start([posed](const Ticket&) { return std::make_shared<ScenePicker>(*posed); },
               [this, meshes, poses](std::shared_ptr<ScenePicker> picker) {
                   if (meshes != meshes_) return; // the meshes changed meanwhile: a newer job comes
                   picker_ = std::move(picker);
                   pickerMeshes_ = meshes;
                   pickerPoses_ = poses;
                   ++builtHere_;
                   emit arrived();
               });
}

const std::vector<NodeIcon>& ViewPicking::icons(const Scene& document, double seconds) {
    if (iconPoses_ != poses_) {
        Scene storage;
        icons_ = nodeIcons(posedAt(document, seconds, storage));
        iconPoses_ = poses_;
    }
    return icons_;
}

} // namespace glint::editor
