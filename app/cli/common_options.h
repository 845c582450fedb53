#pragma once
// Options that mean the same in every subcommand (docs/CLI.md: --size WxH, --spp, --seed, --bounces,
// --config, --camera, --exposure, --tonemap, --env, --out). Registered in one place so names,
// defaults and validation never drift apart between render, bench and encode.
#include "renderer/output/render_plan.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace glint::cli {

using Size = renderer::ImageSize;

// The render overrides every subcommand shares, plus --strict.
struct CommonRenderOptions : renderer::RenderOverrides {
    bool strict = false;
};

// Parses "WxH" (1..16384 each); throws CLI::ValidationError otherwise.
Size parseSize(const std::string& text);

void addCommonRenderOptions(CLI::App& cmd, CommonRenderOptions& options);

} // namespace glint::cli
