#include "history.h"

#include "command_json.h"

#include <stdexcept>

namespace glint {
namespace {

bool mayMerge(const Command& previous, const Command& next) {
    return previous.interaction != 0 && previous.interaction == next.interaction && !previous.mergeKey().empty() &&
           previous.mergeKey() == next.mergeKey();
}

} // namespace

History::History(Scene& scene, HistoryLimits limits) : scene_(scene), limits_(limits) {}

ChangeSet History::push(CommandPtr command) {
    ChangeSet changes = command->apply(scene_);
    if (openMacro_) {
        Command* last = openMacro_->lastChild();
        if (!(last && mayMerge(*last, *command) && last->mergeWith(*command))) openMacro_->appendApplied(std::move(command));
        notifyChange(changes);
        return changes;
    }
    discardRedo();
    if (!mergeIntoTop(*command)) record(std::move(command));
    enforceBounds();
    notifyChange(changes);
    notifyIndex();
    return changes;
}

bool History::canUndo() const { return !inMacro() && index_ > 0; }
bool History::canRedo() const { return !inMacro() && index_ < commands_.size(); }

ChangeSet History::undo() {
    refuseInMacro("undo");
    if (!canUndo()) return {};
    ChangeSet changes = commands_[index_ - 1]->revert(scene_);
    --index_;
    notifyChange(changes);
    notifyIndex();
    return changes;
}

ChangeSet History::redo() {
    refuseInMacro("redo");
    if (!canRedo()) return {};
    ChangeSet changes = commands_[index_]->apply(scene_);
    ++index_;
    notifyChange(changes);
    notifyIndex();
    return changes;
}

ChangeSet History::jumpTo(std::size_t index) {
    refuseInMacro("jump");
    if (index > commands_.size()) throw std::out_of_range("History::jumpTo: no step " + std::to_string(index));
    ChangeSet changes;
    for (; index_ > index; --index_) changes.merge(commands_[index_ - 1]->revert(scene_));
    for (; index_ < index; ++index_) changes.merge(commands_[index_]->apply(scene_));
    notifyChange(changes);
    notifyIndex();
    return changes;
}

ChangeSet History::revertInteraction(std::uint64_t interaction) {
    refuseInMacro("revert");
    ChangeSet changes;
    if (interaction == 0) return changes;
    const std::size_t before = index_;
    for (; index_ > 0 && commands_[index_ - 1]->interaction == interaction; --index_)
        changes.merge(commands_[index_ - 1]->revert(scene_));
    if (index_ == before) return changes;
    discardRedo();
    notifyChange(changes);
    notifyIndex();
    return changes;
}

void History::beginMacro(std::string label) {
    if (macroDepth_++ == 0) openMacro_ = std::make_unique<MacroCommand>(std::move(label));
}

void History::endMacro() {
    if (macroDepth_ == 0) throw std::logic_error("History::endMacro without beginMacro");
    if (--macroDepth_ > 0) return;
    std::unique_ptr<MacroCommand> macro = std::move(openMacro_);
    if (macro->empty()) return;
    discardRedo();
    macro->interaction = macro->childrenInteraction();
    if (mergeIntoTop(*macro)) {
        notifyIndex();
        return;
    }
    record(std::move(macro));
    enforceBounds();
    notifyIndex();
}

void History::setClean() {
    clean_ = index_;
    notifyIndex();
}

std::vector<std::string> History::labels() const {
    std::vector<std::string> out;
    out.reserve(commands_.size());
    for (const CommandPtr& command : commands_) out.push_back(command->label());
    return out;
}

void History::clear() {
    refuseInMacro("clear");
    clean_ = isClean() ? std::optional<std::size_t>(0) : std::nullopt;
    commands_.clear();
    index_ = 0;
    bytes_ = 0;
    notifyIndex();
}

nlohmann::json History::log() const {
    nlohmann::json entries = nlohmann::json::array();
    for (std::size_t i = 0; i < index_; ++i) entries.push_back(commandToJson(*commands_[i]));
    return entries;
}

History::ListenerId History::addChangeListener(ChangeListener listener) {
    changeListeners_.emplace(++lastListener_, std::move(listener));
    return lastListener_;
}

History::ListenerId History::addIndexListener(IndexListener listener) {
    indexListeners_.emplace(++lastListener_, std::move(listener));
    return lastListener_;
}

void History::removeListener(ListenerId id) {
    changeListeners_.erase(id);
    indexListeners_.erase(id);
}

bool History::mergeIntoTop(const Command& command) {
    if (index_ == 0) return false;
    Command& top = *commands_[index_ - 1];
    if (!mayMerge(top, command)) return false;
    const std::size_t before = top.memoryBytes();
    if (!top.mergeWith(command)) return false;
    bytes_ = bytes_ - before + top.memoryBytes();
    if (clean_ == index_) clean_.reset(); // the saved state is no longer on the stack
    return true;
}

void History::record(CommandPtr command) {
    bytes_ += command->memoryBytes();
    commands_.push_back(std::move(command));
    ++index_;
}

void History::discardRedo() {
    if (index_ == commands_.size()) return;
    if (clean_ && *clean_ > index_) clean_.reset();
    for (std::size_t i = index_; i < commands_.size(); ++i) bytes_ -= commands_[i]->memoryBytes();
    commands_.erase(commands_.begin() + static_cast<std::ptrdiff_t>(index_), commands_.end());
}

// Drops the oldest commands; called right after recording, when index_ == count().
void History::enforceBounds() {
    const auto tooMany = [&] { return commands_.size() > limits_.maxDepth || bytes_ > limits_.maxBytes; };
    while (commands_.size() > 1 && tooMany()) {
        bytes_ -= commands_.front()->memoryBytes();
        commands_.erase(commands_.begin());
        --index_;
        if (clean_) clean_ = *clean_ == 0 ? std::nullopt : std::optional<std::size_t>(*clean_ - 1);
    }
}

void History::notifyChange(const ChangeSet& changes) const {
    for (const auto& [id, listener] : changeListeners_) listener(changes);
}

void History::notifyIndex() const {
    for (const auto& [id, listener] : indexListeners_) listener(index_);
}

void History::refuseInMacro(const char* what) const {
    if (inMacro()) throw std::logic_error(std::string("History: cannot ") + what + " while a macro is open");
}

} // namespace glint
