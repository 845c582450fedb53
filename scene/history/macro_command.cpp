#include "macro_command.h"

#include "command_json.h"

namespace glint {

MacroCommand::MacroCommand(std::string label, std::vector<CommandPtr> children)
    : label_(std::move(label)), children_(std::move(children)) {}

ChangeSet MacroCommand::apply(Scene& scene) {
    ChangeSet changes;
    std::size_t applied = 0;
    try {
        for (; applied < children_.size(); ++applied) changes.merge(children_[applied]->apply(scene));
    } catch (...) {
        while (applied > 0) children_[--applied]->revert(scene);
        throw;
    }
    return changes;
}

ChangeSet MacroCommand::revert(Scene& scene) {
    ChangeSet changes;
    for (auto it = children_.rbegin(); it != children_.rend(); ++it) changes.merge((*it)->revert(scene));
    return changes;
}

std::size_t MacroCommand::memoryBytes() const {
    std::size_t bytes = sizeof(*this) + label_.size();
    for (const CommandPtr& child : children_) bytes += child->memoryBytes();
    return bytes;
}

std::string MacroCommand::mergeKey() const {
    std::string key = "macro";
    for (const CommandPtr& child : children_) {
        const std::string childKey = child->mergeKey();
        if (childKey.empty()) return {};
        key += '|' + childKey;
    }
    return children_.empty() ? std::string{} : key;
}

bool MacroCommand::mergeWith(const Command& next) {
    const auto* other = dynamic_cast<const MacroCommand*>(&next);
    if (!other || other->children_.size() != children_.size() || other->mergeKey() != mergeKey()) return false;
    for (std::size_t i = 0; i < children_.size(); ++i)
        if (!children_[i]->mergeWith(*other->children_[i])) return false; // same keys: children always merge
    return true;
}

std::uint64_t MacroCommand::childrenInteraction() const {
    if (children_.empty()) return 0;
    const std::uint64_t first = children_.front()->interaction;
    for (const CommandPtr& child : children_)
        if (child->interaction != first) return 0;
    return first;
}

nlohmann::json MacroCommand::toJson() const {
    nlohmann::json children = nlohmann::json::array();
    for (const CommandPtr& child : children_) children.push_back(commandToJson(*child));
    return {{"label", label_}, {"children", std::move(children)}};
}

CommandPtr MacroCommand::fromJson(const nlohmann::json& j) {
    std::vector<CommandPtr> children;
    for (const nlohmann::json& child : j.at("children")) children.push_back(commandFromJson(child));
    return std::make_unique<MacroCommand>(j.at("label").get<std::string>(), std::move(children));
}

} // namespace glint
