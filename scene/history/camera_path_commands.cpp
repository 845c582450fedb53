#include "camera_path_commands.h"

#include "value_json.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace glint {
namespace {

CameraPath& pathOf(Scene& scene, NodeId camera) {
    auto* component = std::get_if<Camera>(&scene.component(camera));
    if (!component) throw std::invalid_argument("node " + std::to_string(camera.value) + " is not a camera");
    return component->path;
}

const CameraKey& keyAt(const CameraPath& path, std::size_t index) {
    if (index >= path.keys.size()) throw std::out_of_range("no camera key " + std::to_string(index));
    return path.keys[index];
}

// Where a key at `time` goes to keep the keys strictly increasing; throws if the time is taken.
std::size_t sortedSlot(const CameraPath& path, double time) {
    auto it = std::lower_bound(path.keys.begin(), path.keys.end(), time,
                               [](const CameraKey& key, double t) { return key.time < t; });
    if (it != path.keys.end() && it->time == time)
        throw std::invalid_argument("a camera key at time " + std::to_string(time) + " exists already");
    return static_cast<std::size_t>(it - path.keys.begin());
}

void insertAt(CameraPath& path, std::size_t index, const CameraKey& key) {
    path.keys.insert(path.keys.begin() + static_cast<std::ptrdiff_t>(index), key);
}

void eraseAt(CameraPath& path, std::size_t index) { path.keys.erase(path.keys.begin() + static_cast<std::ptrdiff_t>(index)); }

ChangeSet pathChange(NodeId camera) { return nodeChange(Change::Camera, camera).add(Change::Animation); }

} // namespace

// --- AddCameraKey -------------------------------------------------------------------------------

ChangeSet AddCameraKey::apply(Scene& scene) {
    CameraPath& path = pathOf(scene, camera_);
    index_ = sortedSlot(path, key_.time);
    insertAt(path, index_, key_);
    return pathChange(camera_);
}

ChangeSet AddCameraKey::revert(Scene& scene) {
    eraseAt(pathOf(scene, camera_), index_);
    return pathChange(camera_);
}

nlohmann::json AddCameraKey::toJson() const { return {{"camera", camera_}, {"key", key_}}; }

CommandPtr AddCameraKey::fromJson(const nlohmann::json& j) {
    return std::make_unique<AddCameraKey>(j.at("camera").get<NodeId>(), j.at("key").get<CameraKey>());
}

// --- RemoveCameraKey ----------------------------------------------------------------------------

ChangeSet RemoveCameraKey::apply(Scene& scene) {
    CameraPath& path = pathOf(scene, camera_);
    removed_ = keyAt(path, index_);
    eraseAt(path, index_);
    return pathChange(camera_);
}

ChangeSet RemoveCameraKey::revert(Scene& scene) {
    insertAt(pathOf(scene, camera_), index_, removed_);
    return pathChange(camera_);
}

nlohmann::json RemoveCameraKey::toJson() const { return {{"camera", camera_}, {"index", index_}}; }

CommandPtr RemoveCameraKey::fromJson(const nlohmann::json& j) {
    return std::make_unique<RemoveCameraKey>(j.at("camera").get<NodeId>(), j.at("index").get<std::size_t>());
}

// --- MoveCameraKey ------------------------------------------------------------------------------

ChangeSet MoveCameraKey::apply(Scene& scene) {
    CameraPath& path = pathOf(scene, camera_);
    CameraKey key = keyAt(path, index_);
    oldTime_ = key.time;
    if (newTime_ == oldTime_) {
        newIndex_ = index_;
        return pathChange(camera_);
    }
    eraseAt(path, index_);
    try {
        newIndex_ = sortedSlot(path, newTime_);
    } catch (...) {
        insertAt(path, index_, key); // leave the path as it was
        throw;
    }
    key.time = newTime_;
    insertAt(path, newIndex_, key);
    return pathChange(camera_);
}

ChangeSet MoveCameraKey::revert(Scene& scene) {
    CameraPath& path = pathOf(scene, camera_);
    CameraKey key = path.keys.at(newIndex_);
    eraseAt(path, newIndex_);
    key.time = oldTime_;
    insertAt(path, index_, key);
    return pathChange(camera_);
}

std::string MoveCameraKey::mergeKey() const { return "move_camera_key:" + std::to_string(camera_.value); }

// The next move continues this drag only if it grabs the key where this one left it.
bool MoveCameraKey::mergeWith(const Command& next) {
    const auto* move = dynamic_cast<const MoveCameraKey*>(&next);
    if (!move || move->camera_ != camera_ || move->index_ != newIndex_) return false;
    newTime_ = move->newTime_;
    newIndex_ = move->newIndex_;
    return true;
}

nlohmann::json MoveCameraKey::toJson() const {
    return {{"camera", camera_}, {"index", index_}, {"time", newTime_}};
}

CommandPtr MoveCameraKey::fromJson(const nlohmann::json& j) {
    return std::make_unique<MoveCameraKey>(j.at("camera").get<NodeId>(), j.at("index").get<std::size_t>(),
                                           j.at("time").get<double>());
}

// --- EditCameraKey ------------------------------------------------------------------------------

ChangeSet EditCameraKey::apply(Scene& scene) {
    CameraPath& path = pathOf(scene, camera_);
    old_ = keyAt(path, index_);
    CameraKey edited = new_;
    edited.time = old_.time;
    path.keys[index_] = edited;
    return pathChange(camera_);
}

ChangeSet EditCameraKey::revert(Scene& scene) {
    pathOf(scene, camera_).keys.at(index_) = old_;
    return pathChange(camera_);
}

std::string EditCameraKey::mergeKey() const {
    return "edit_camera_key:" + std::to_string(camera_.value) + ":" + std::to_string(index_);
}

bool EditCameraKey::mergeWith(const Command& next) {
    const auto* edit = dynamic_cast<const EditCameraKey*>(&next);
    if (!edit || edit->camera_ != camera_ || edit->index_ != index_) return false;
    new_ = edit->new_;
    return true;
}

nlohmann::json EditCameraKey::toJson() const { return {{"camera", camera_}, {"index", index_}, {"key", new_}}; }

CommandPtr EditCameraKey::fromJson(const nlohmann::json& j) {
    return std::make_unique<EditCameraKey>(j.at("camera").get<NodeId>(), j.at("index").get<std::size_t>(),
                                           j.at("key").get<CameraKey>());
}

// --- SetCameraPathMode --------------------------------------------------------------------------

ChangeSet SetCameraPathMode::apply(Scene& scene) {
    CameraPath& path = pathOf(scene, camera_);
    oldRotation_ = path.rotation;
    oldConstantSpeed_ = path.constantSpeed;
    path.rotation = rotation_;
    path.constantSpeed = constantSpeed_;
    return pathChange(camera_);
}

ChangeSet SetCameraPathMode::revert(Scene& scene) {
    CameraPath& path = pathOf(scene, camera_);
    path.rotation = oldRotation_;
    path.constantSpeed = oldConstantSpeed_;
    return pathChange(camera_);
}

nlohmann::json SetCameraPathMode::toJson() const {
    return {{"camera", camera_}, {"rotation", rotation_}, {"constantSpeed", constantSpeed_}};
}

CommandPtr SetCameraPathMode::fromJson(const nlohmann::json& j) {
    return std::make_unique<SetCameraPathMode>(j.at("camera").get<NodeId>(), j.at("rotation").get<RotationInterpolation>(),
                                               j.at("constantSpeed").get<bool>());
}

} // namespace glint
