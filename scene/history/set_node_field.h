#pragma once
// Sets one field of one node (name, transform, visibility, component): old and new values by
// stable node id. Edits of the same field of the same node within one interaction merge.
#include "command.h"
#include "node_fields.h"
#include "value_json.h"

#include <memory>
#include <stdexcept>
#include <string>

namespace glint {

template <class Field>
class SetNodeField final : public Command {
public:
    using Value = typename Field::Value;

    SetNodeField(NodeId node, Value value) : node_(node), new_(std::move(value)) {}

    ChangeSet apply(Scene& scene) override {
        old_ = Field::get(scene.at(node_));
        Field::set(scene, node_, new_);
        return Field::changes(node_, old_, new_);
    }
    ChangeSet revert(Scene& scene) override {
        Field::set(scene, node_, old_);
        return Field::changes(node_, new_, old_);
    }

    std::string label() const override { return Field::label; }
    std::string typeName() const override { return Field::type; }
    std::string mergeKey() const override { return std::string(Field::type) + ":" + std::to_string(node_.value); }
    bool mergeWith(const Command& next) override {
        const auto* same = dynamic_cast<const SetNodeField*>(&next);
        if (!same || same->node_ != node_) return false;
        new_ = same->new_;
        return true;
    }
    std::size_t memoryBytes() const override { return sizeof(*this) + approxValueBytes(old_) + approxValueBytes(new_); }

    nlohmann::json toJson() const override { return {{"node", node_}, {"value", new_}}; }
    static CommandPtr fromJson(const nlohmann::json& j) {
        return std::make_unique<SetNodeField>(j.at("node").get<NodeId>(), j.at("value").get<Value>());
    }

    NodeId node() const { return node_; }
    const Value& newValue() const { return new_; }

private:
    static std::size_t approxValueBytes(const Value& value) {
        if constexpr (std::is_same_v<Value, std::string>) return value.size();
        else if constexpr (std::is_same_v<Value, Component>) {
            const auto* camera = std::get_if<Camera>(&value);
            return camera ? camera->path.keys.size() * sizeof(CameraKey) : 0;
        } else return 0;
    }

    NodeId node_;
    Value new_;
    Value old_{};
};

using RenameNode = SetNodeField<NameField>;
using SetTransform = SetNodeField<TransformField>;
using SetVisibility = SetNodeField<VisibilityField>;
using SetComponent = SetNodeField<ComponentField>;

} // namespace glint
