#pragma once
// The undo history of one Scene. Every edit is a Command pushed here; push applies it.
//
// Stack: commands [0, count()); index() of them are applied. undo() reverts command index-1,
// redo() applies command index. Pushing while commands are undone discards them (no branches).
//
// Merge rule: a pushed command merges into the previous one (top of the stack, or the last
// command of the open macro) only when both carry the same non-zero interaction serial and the
// same non-empty mergeKey(). Serials come from beginInteraction(): a slider or gizmo drag takes
// one serial and tags every command of the drag with it, so the drag is one undo step. Nothing
// merges by time, so a replay merges exactly as the session did.
//
// Macros: beginMacro/endMacro group the commands pushed between them (each applied at once)
// into one MacroCommand that undoes and redoes as one step; nested pairs join the outer one;
// an empty macro leaves no step. Undo, redo and jumps are refused (std::logic_error) while a
// macro is open.
//
// Clean state: setClean() marks the current index as the saved state, isClean() says whether
// the scene is back there. When the clean command is discarded (pushing after undoing past it,
// dropped by a bound) or changed (a merge into the clean top), the clean state is unreachable
// until the next setClean().
//
// Bounds: at most maxDepth commands and about maxBytes of command memory (Command::memoryBytes);
// the oldest commands are dropped first, and the newest one always stays.
//
// Listeners: change listeners get the ChangeSet of every push, undo, redo and jump (after the
// scene changed); index listeners get the new index whenever the index, count or clean state
// may have changed, for the history view. Neither may edit the history from inside the call.
#include "command.h"
#include "macro_command.h"

#include <functional>
#include <map>
#include <optional>
#include <vector>

namespace glint {

struct HistoryLimits {
    std::size_t maxDepth = 1000;
    std::size_t maxBytes = std::size_t{512} << 20;
};

class History {
public:
    using ChangeListener = std::function<void(const ChangeSet&)>;
    using IndexListener = std::function<void(std::size_t index)>;
    using ListenerId = int;

    explicit History(Scene& scene, HistoryLimits limits = {});

    // Applies `command` (exceptions propagate, nothing is recorded) and records it.
    ChangeSet push(CommandPtr command);
    bool canUndo() const;
    bool canRedo() const;
    ChangeSet undo();
    ChangeSet redo();
    ChangeSet jumpTo(std::size_t index); // undo or redo until index() == index
    // Undoes and forgets the steps on top that belong to `interaction` (a cancelled drag): no redo
    // step is left for an edit the user took back with Esc. Nothing happens for another interaction.
    ChangeSet revertInteraction(std::uint64_t interaction);

    std::uint64_t beginInteraction() { return ++lastInteraction_; }

    void beginMacro(std::string label);
    void endMacro();
    bool inMacro() const { return openMacro_ != nullptr; }

    void setClean();
    bool isClean() const { return clean_ == index_; }
    std::optional<std::size_t> cleanIndex() const { return clean_; }

    std::size_t index() const { return index_; }
    std::size_t count() const { return commands_.size(); }
    std::string label(std::size_t i) const { return commands_.at(i)->label(); }
    std::vector<std::string> labels() const;
    std::size_t memoryBytes() const { return bytes_; }
    const HistoryLimits& limits() const { return limits_; }
    void clear(); // forgets every command; the scene stays as it is

    // The applied commands [0, index()) as a replayable log (command_json.h).
    nlohmann::json log() const;

    ListenerId addChangeListener(ChangeListener listener);
    ListenerId addIndexListener(IndexListener listener);
    void removeListener(ListenerId id);

private:
    bool mergeIntoTop(const Command& command);
    void record(CommandPtr command);
    void discardRedo();
    void enforceBounds();
    void notifyChange(const ChangeSet& changes) const;
    void notifyIndex() const;
    void refuseInMacro(const char* what) const;

    Scene& scene_;
    HistoryLimits limits_;
    std::vector<CommandPtr> commands_;
    std::size_t index_ = 0;
    std::optional<std::size_t> clean_ = 0;
    std::size_t bytes_ = 0;
    std::uint64_t lastInteraction_ = 0;
    std::unique_ptr<MacroCommand> openMacro_;
    int macroDepth_ = 0;
    ListenerId lastListener_ = 0;
    std::map<ListenerId, ChangeListener> changeListeners_;
    std::map<ListenerId, IndexListener> indexListeners_;
};

} // namespace glint
