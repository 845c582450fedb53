#pragma once
// Joins modular GLSL files into one source string. Each `#include "path"` is replaced by that file
// (resolved next to the including file first, then from the shaders/ root) at most once per
// program, so chunks need no include guards. `#line 1 N` directives number each file, and the
// table `files` maps that number back to a name for compiler logs. No GL in here.
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace glint::gl {

using ShaderLookup = std::function<std::optional<std::string_view>(std::string_view name)>;

struct ResolvedShader {
    std::string text;               // ready for glShaderSource
    std::vector<std::string> files; // source-string number -> file name; 0 is the prelude
};

// `prelude` goes right after `#version` (defines, macros). Throws std::runtime_error naming the
// including file and line for a missing file, a malformed directive, or include nesting deeper than 32.
ResolvedShader resolveIncludes(std::string_view mainFile, std::string_view version, std::string_view prelude,
                               const ShaderLookup& lookup);

// Rewrites "0:12(3): error" (Mesa) and "0(12) : error" (NVIDIA) as "file.glsl:12: error".
std::string mapLogToFiles(std::string_view log, const std::vector<std::string>& files);

} // namespace glint::gl
