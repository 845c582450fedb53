#pragma once
// Several commands that undo and redo as one step (History::beginMacro/endMacro).
#include "command.h"

#include <vector>

namespace glint {

class MacroCommand final : public Command {
public:
    explicit MacroCommand(std::string label, std::vector<CommandPtr> children = {});

    // Applies the children in order; if one throws, those already applied are reverted.
    ChangeSet apply(Scene& scene) override;
    ChangeSet revert(Scene& scene) override; // children in reverse order
    std::string label() const override { return label_; }
    std::string typeName() const override { return "macro"; }
    std::size_t memoryBytes() const override;
    nlohmann::json toJson() const override;
    static CommandPtr fromJson(const nlohmann::json& j);

    // A continuous edit of several nodes at once (a field dragged with many selected) is a macro per
    // step: it merges with the previous step's macro when their children pair up one to one with
    // the same merge keys (History gives the macro its children's interaction).
    std::string mergeKey() const override;
    bool mergeWith(const Command& next) override;
    // The interaction all children share (0 when they differ or have none).
    std::uint64_t childrenInteraction() const;

    // For History while the macro is open: the child was applied already.
    void appendApplied(CommandPtr child) { children_.push_back(std::move(child)); }
    Command* lastChild() { return children_.empty() ? nullptr : children_.back().get(); }
    bool empty() const { return children_.empty(); }
    std::size_t size() const { return children_.size(); }

private:
    std::string label_;
    std::vector<CommandPtr> children_;
};

} // namespace glint
