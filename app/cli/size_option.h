#pragma once
// --size WxH of every subcommand, parsed without CLI11 so that the scene-only (sanitizer and fuzz)
// build compiles it too (tests/fuzz/fuzz_cli_options.cpp).
#include <string>

namespace glint::cli {

constexpr int kMaxImageDimension = 16384;

struct WidthHeight {
    int width = 0;
    int height = 0;
};

// "WxH" (or "WXH") with 1 <= W, H <= 16384; throws std::invalid_argument saying what is wrong.
WidthHeight parseWidthHeight(const std::string& text);

} // namespace glint::cli
