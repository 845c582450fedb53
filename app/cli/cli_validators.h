#pragma once
// CLI11 helpers shared by the subcommands: parsers that throw std::invalid_argument become
// validators, so a bad value is a usage error (exit code 2) with the parser's own message.
#include "frame_timing.h"

#include <CLI/CLI.hpp>

#include <functional>
#include <optional>
#include <string>

namespace glint::cli {

std::function<std::string(std::string&)> rejection(std::function<void(const std::string&)> parse);

// A number in [low, high]; CLI::Range lets NaN through (every comparison with NaN is false).
CLI::Validator finiteIn(double low, double high);

// --frames A-B and --fps N[/D], as render --animation and encode both take them.
void addFrameOptions(CLI::App& cmd, std::optional<FrameRange>& frames, std::optional<Fps>& fps);

} // namespace glint::cli
