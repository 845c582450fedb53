#pragma once
// The GLSL sources of shaders/, embedded at build time and sorted by name ("pathtrace/main.frag.glsl").
#include <optional>
#include <span>
#include <string_view>

namespace glint::shaders {

struct EmbeddedShader {
    std::string_view name;
    std::string_view source;
};

std::span<const EmbeddedShader> all();
std::optional<std::string_view> find(std::string_view name);

} // namespace glint::shaders
