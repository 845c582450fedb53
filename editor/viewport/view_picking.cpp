#include "editor/viewport/view_picking.h"

#include "renderer/gpu_scene/prepared_scene.h"
#include "scene/anim/scene_at_time.h"

#include <QMetaObject>

#include <atomic>

#include <utility>

namespace glint::editor {

namespace {

// Changes after which a picker's mesh part (which meshes, instanced where, visible or not) may be
// out of date. Transforms, lights, materials, cameras and names leave it as it is.
bool changesMeshes(const ChangeSet& changes) {
    return changes.has(Change::Geometry) || changes.has(Change::Structure) || changes.has(Change::Visibility);
}

} // namespace

struct ViewPicking::Job {
    Scene posed;
    std::uint64_t meshes = 0, poses = 0;
    std::atomic<bool> cancelled{false};
    std::shared_ptr<ScenePicker> result; // written by the worker before it posts back
};

ViewPicking::ViewPicking(QObject* parent) : QObject(parent) { pool_.setMaxThreadCount(1); }

ViewPicking::~ViewPicking() {
    dropJob();
    pool_.waitForDone(); // at most one picker build
}

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
    dropJob(); // a picker-only job in flight is superseded
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
    if (!preparationComing && !(job_ && job_->meshes == meshes_)) startJob(document, seconds);
    return empty_;
}

void ViewPicking::dropJob() {
    if (job_) job_->cancelled = true;
    job_.reset();
}

void ViewPicking::startJob(const Scene& document, double seconds) {
    auto job = std::make_shared<Job>();
    job->posed = sceneAnimates(document) ? sceneAt(document, seconds) : document; // the worker's own copy
    job->meshes = meshes_;
    job->poses = poses_;
    dropJob();
    job_ = job;
    pool_.start([this, job] {
        if (job->cancelled) return; // superseded while it waited
        job->result = std::make_shared<ScenePicker>(job->posed);
        QMetaObject::invokeMethod(this, [this, job] {
            if (job != job_ || job->meshes != meshes_) return;
            job_.reset();
            picker_ = std::move(job->result);
            pickerMeshes_ = job->meshes;
            pickerPoses_ = job->poses;
            ++builtHere_;
            emit arrived();
        }, Qt::QueuedConnection);
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
