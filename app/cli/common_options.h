#pragma once
// Options that mean the same in every subcommand (CONTRACTS.md: --size WxH, --spp, --seed, --bounces,
// --config, --camera, --exposure, --tonemap, --env, --out). Registered in one place so names,
// defaults and validation never drift apart between render, bench and encode.
#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace glint::cli {

struct Size {
    int width = 0;
    int height = 0;
};

struct CommonRenderOptions {
    std::optional<Size> size;         // default: the project's render size
    std::optional<int> spp;           // default: the configuration's / project's
    std::uint32_t seed = 0;
    std::optional<int> bounces;
    std::optional<std::string> config;
    std::optional<std::string> camera;
    double exposure = 0.0;            // EV added to the camera's
    std::optional<std::string> tonemap;
    std::optional<std::string> env;
    bool requireGpu = false;
    bool strict = false;
};

// Parses "WxH" (1..16384 each); throws CLI::ValidationError otherwise.
Size parseSize(const std::string& text);

void addCommonRenderOptions(CLI::App& cmd, CommonRenderOptions& options);

} // namespace glint::cli
