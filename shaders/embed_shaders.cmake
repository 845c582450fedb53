# Writes OUTPUT: a sorted table of {name, source} for FILES (paths relative to SHADER_DIR).
# Sources become raw string literals split into chunks, so no compiler limit on literal length bites.
set(body "")
foreach(name IN LISTS FILES)
  file(READ ${SHADER_DIR}/${name} text)
  string(FIND "${text}" ")glsl\"" clash)
  if(NOT clash EQUAL -1)
    message(FATAL_ERROR "${name}: contains the literal delimiter )glsl\"")
  endif()
  set(chunks "")
  string(LENGTH "${text}" length)
  set(offset 0)
  while(offset LESS length)
    string(SUBSTRING "${text}" ${offset} 8000 piece)
    string(APPEND chunks "R\"glsl(${piece})glsl\"\n")
    math(EXPR offset "${offset} + 8000")
  endwhile()
  if(chunks STREQUAL "")
    set(chunks "\"\"")
  endif()
  string(APPEND body "    {\"${name}\", ${chunks}},\n")
endforeach()
file(WRITE ${OUTPUT}.tmp "// Generated from shaders/**/*.glsl by embed_shaders.cmake. Do not edit.
#include \"shaders/embedded_shaders.h\"

#include <algorithm>
#include <array>

namespace glint::shaders {
namespace {
const EmbeddedShader table[] = {
${body}};
} // namespace

std::span<const EmbeddedShader> all() { return table; }

std::optional<std::string_view> find(std::string_view name) {
    const auto* it = std::lower_bound(std::begin(table), std::end(table), name,
                                      [](const EmbeddedShader& s, std::string_view n) { return s.name < n; });
    if (it == std::end(table) || it->name != name) return std::nullopt;
    return it->source;
}
} // namespace glint::shaders
")
file(COPY_FILE ${OUTPUT}.tmp ${OUTPUT} ONLY_IF_DIFFERENT)
file(REMOVE ${OUTPUT}.tmp)
