#pragma once
// Builds the commands that add an imported scene to the open one: its assets under fresh ids and
// its nodes under fresh ids, references remapped. Pushed inside one macro, the import is one
// undo step and replays like any other edit.
#include "scene/core/scene.h"
#include "scene/history/command.h"

#include <vector>

namespace glint::editor {

// Commands in the order they must be pushed (assets before the nodes that use them).
// `target` supplies the next free ids, so the commands name the ids they will assign. The assets of
// `imported` are moved into the commands (left empty); its nodes are copied.
std::vector<CommandPtr> mergeCommands(const Scene& target, Scene&& imported);

} // namespace glint::editor
