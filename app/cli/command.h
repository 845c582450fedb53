#pragma once
// Each subcommand registers its options on the parser and leaves behind the action to run once
// parsing succeeded. Actions return an exit code and report their own errors.
#include <CLI/CLI.hpp>

#include <functional>

namespace glint::cli {

using Action = std::function<int()>;

void addInfoCommand(CLI::App& app, Action& action);
void addConvertCommand(CLI::App& app, Action& action);
void addRenderCommand(CLI::App& app, Action& action);
void addEncodeCommand(CLI::App& app, Action& action);
void addBenchCommand(CLI::App& app, Action& action);

// Runs the command line (argv without the editor case). Never throws.
int runCommandLine(int argc, char** argv);

} // namespace glint::cli
