#pragma once
// Commands as JSON, for session logs that can be replayed (bug reports, tests). A command is
// {"type": name, "interaction": serial, ...its own fields}; a log is an array of them.
// The registry is a constant table from type name to factory: no registration at start-up.
#include "command.h"

#include <nlohmann/json.hpp>

#include <span>
#include <string_view>

namespace glint {

using CommandFactory = CommandPtr (*)(const nlohmann::json&);

struct CommandType {
    std::string_view name;
    CommandFactory fromJson;
};

// Every command type, in a fixed order.
std::span<const CommandType> commandTypes();

nlohmann::json commandToJson(const Command& command);
// Throws std::invalid_argument naming an unknown type; nlohmann::json::exception for a
// missing or mistyped field.
CommandPtr commandFromJson(const nlohmann::json& j);

// Applies every command of a log in order; returns what changed overall.
ChangeSet replayLog(Scene& scene, const nlohmann::json& log);

} // namespace glint
