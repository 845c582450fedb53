#pragma once
// Edits of a camera node's path: add, remove, move (in time) and edit keys, and its modes.
// Keys stay sorted by strictly increasing time: a command that would break that throws
// std::invalid_argument without changing the scene. Keys are named by index.
#include "command.h"

#include <cstddef>

namespace glint {

class AddCameraKey final : public Command {
public:
    AddCameraKey(NodeId camera, CameraKey key) : camera_(camera), key_(key) {}
    ChangeSet apply(Scene& scene) override;
    ChangeSet revert(Scene& scene) override;
    std::string label() const override { return "Add camera key"; }
    std::string typeName() const override { return "add_camera_key"; }
    std::size_t memoryBytes() const override { return sizeof(*this); }
    nlohmann::json toJson() const override;
    static CommandPtr fromJson(const nlohmann::json& j);

private:
    NodeId camera_;
    CameraKey key_;
    std::size_t index_ = 0;
};

class RemoveCameraKey final : public Command {
public:
    RemoveCameraKey(NodeId camera, std::size_t index) : camera_(camera), index_(index) {}
    ChangeSet apply(Scene& scene) override;
    ChangeSet revert(Scene& scene) override;
    std::string label() const override { return "Remove camera key"; }
    std::string typeName() const override { return "remove_camera_key"; }
    std::size_t memoryBytes() const override { return sizeof(*this); }
    nlohmann::json toJson() const override;
    static CommandPtr fromJson(const nlohmann::json& j);

private:
    NodeId camera_;
    std::size_t index_;
    CameraKey removed_;
};

// Moves a key to a new time; it may pass its neighbours, so its index can change. Dragging a
// key along the timeline merges within the interaction.
class MoveCameraKey final : public Command {
public:
    MoveCameraKey(NodeId camera, std::size_t index, double time) : camera_(camera), index_(index), newTime_(time) {}
    ChangeSet apply(Scene& scene) override;
    ChangeSet revert(Scene& scene) override;
    std::string label() const override { return "Move camera key"; }
    std::string typeName() const override { return "move_camera_key"; }
    std::string mergeKey() const override;
    bool mergeWith(const Command& next) override;
    std::size_t memoryBytes() const override { return sizeof(*this); }
    nlohmann::json toJson() const override;
    static CommandPtr fromJson(const nlohmann::json& j);

private:
    NodeId camera_;
    std::size_t index_;
    double newTime_;
    double oldTime_ = 0.0;
    std::size_t newIndex_ = 0;
};

// Replaces a key's pose and lens (position, orientation, fov, focus, aperture). Its time stays:
// MoveCameraKey changes times, so that this command can never reorder keys.
class EditCameraKey final : public Command {
public:
    EditCameraKey(NodeId camera, std::size_t index, CameraKey key) : camera_(camera), index_(index), new_(key) {}
    ChangeSet apply(Scene& scene) override;
    ChangeSet revert(Scene& scene) override;
    std::string label() const override { return "Edit camera key"; }
    std::string typeName() const override { return "edit_camera_key"; }
    std::string mergeKey() const override;
    bool mergeWith(const Command& next) override;
    std::size_t memoryBytes() const override { return sizeof(*this); }
    nlohmann::json toJson() const override;
    static CommandPtr fromJson(const nlohmann::json& j);

private:
    NodeId camera_;
    std::size_t index_;
    CameraKey new_;
    CameraKey old_;
};

// Constant-speed mode and rotation interpolation of a path.
class SetCameraPathMode final : public Command {
public:
    SetCameraPathMode(NodeId camera, RotationInterpolation rotation, bool constantSpeed)
        : camera_(camera), rotation_(rotation), constantSpeed_(constantSpeed) {}
    ChangeSet apply(Scene& scene) override;
    ChangeSet revert(Scene& scene) override;
    std::string label() const override { return "Camera path mode"; }
    std::string typeName() const override { return "set_camera_path_mode"; }
    std::size_t memoryBytes() const override { return sizeof(*this); }
    nlohmann::json toJson() const override;
    static CommandPtr fromJson(const nlohmann::json& j);

private:
    NodeId camera_;
    RotationInterpolation rotation_;
    bool constantSpeed_;
    RotationInterpolation oldRotation_ = RotationInterpolation::Squad;
    bool oldConstantSpeed_ = false;
};

} // namespace glint
