#pragma once
// One undoable edit of a Scene. Commands are values: they name what they edit by stable id
// (never by pointer), carry the new value, and capture the old value when applied, so that
// apply/revert/apply on the same scene state gives the same result every time.
#include "change_set.h"
#include "scene/core/scene.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <memory>
#include <string>

namespace glint {

class Command {
public:
    virtual ~Command() = default;

    // Edits the scene and says what changed. Throws (std::invalid_argument, std::out_of_range)
    // without changing the scene when the command does not fit it (a missing node, ...).
    virtual ChangeSet apply(Scene& scene) = 0;
    // Undoes the last apply exactly; only valid on the state apply left.
    virtual ChangeSet revert(Scene& scene) = 0;

    virtual std::string label() const = 0;    // for the history view
    virtual std::string typeName() const = 0; // the key of command_json.h's registry

    // Commands with the same non-empty key and the same non-zero interaction may merge:
    // mergeWith takes over `next`'s new value and keeps its own old value. Returns false when
    // the two do not fit after all (then both stay on the stack).
    virtual std::string mergeKey() const { return {}; }
    virtual bool mergeWith(const Command& /*next*/) { return false; }

    virtual std::size_t memoryBytes() const = 0; // an estimate, for the history's memory bound

    // What replaying needs: the target ids, the new values and any ids assigned by a first
    // apply (so a replay reproduces them). Old values are captured again on replay.
    virtual nlohmann::json toJson() const = 0;

    // The interaction (a slider or gizmo drag, from History::beginInteraction) this edit belongs
    // to; 0: a one-off edit that never merges.
    std::uint64_t interaction = 0;
};

using CommandPtr = std::unique_ptr<Command>;

} // namespace glint
