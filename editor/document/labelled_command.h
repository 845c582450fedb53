#pragma once
// A command under the editor's own label ("Rotate", "Change exposure") instead of the scene core's
// generic one ("Move", "Edit settings"), so the undo history and Edit > Undo say what happened.
// Everything else is the wrapped command's: what it does, how it merges (a drag is still one
// step), its JSON (a replay gets the core's label back).
#include "scene/history/command.h"

#include <string>
#include <utility>

namespace glint::editor {

class LabelledCommand final : public Command {
public:
    LabelledCommand(CommandPtr inner, std::string label) : inner_(std::move(inner)), label_(std::move(label)) {
        interaction = inner_->interaction;
    }

    ChangeSet apply(Scene& scene) override { return inner_->apply(scene); }
    ChangeSet revert(Scene& scene) override { return inner_->revert(scene); }
    std::string label() const override { return label_; }
    std::string typeName() const override { return inner_->typeName(); }
    std::string mergeKey() const override { return inner_->mergeKey(); }
    // One drag stays one step even if a step of it would be labelled otherwise: the first label stays.
    bool mergeWith(const Command& next) override {
        const auto* labelled = dynamic_cast<const LabelledCommand*>(&next);
        return inner_->mergeWith(labelled ? *labelled->inner_ : next);
    }
    std::size_t memoryBytes() const override { return sizeof(*this) + label_.size() + inner_->memoryBytes(); }
    nlohmann::json toJson() const override { return inner_->toJson(); }

    const Command& inner() const { return *inner_; }

private:
    CommandPtr inner_;
    std::string label_;
};

// `command` under `label`, or as it is when the label is empty or its own.
inline CommandPtr withLabel(CommandPtr command, const std::string& label) {
    if (label.empty() || label == command->label()) return command;
    return std::make_unique<LabelledCommand>(std::move(command), label);
}

} // namespace glint::editor
