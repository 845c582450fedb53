#pragma once
// The options of `glint bench --suite renderer` and `--suite shaders` that plain `glint bench` does
// not have; the shared
// ones (SCENE, --size, --spp, --bounces, --out, --reference-spp) stay with the bench command.
#include "renderer_suite.h"

#include <CLI/CLI.hpp>

#include <memory>
#include <optional>
#include <string>

namespace glint::bench {

struct SuiteCli {
    std::string suite;   // "renderer" or empty
    SuiteOptions options; // suite-only fields filled by the parser
    bool requested() const { return !suite.empty(); }
};

std::shared_ptr<SuiteCli> addRendererSuiteOptions(CLI::App& bench);

// The suite's options after parsing: the bench's shared options where the user gave them (`bench`
// tells which were given), the suite's defaults otherwise.
SuiteOptions suiteOptions(const SuiteCli& cli, const CLI::App& bench, const std::string& scene, const std::string& out,
                          int width, int height, std::optional<int> spp, std::optional<int> bounces, int referenceSpp);

// Runs the suite (renderer, or shaders: shader_suite.h); errors become the one-line message and exit
// code 1 (docs/CLI.md).
int runRendererSuiteCommand(const SuiteOptions& options);

} // namespace glint::bench
