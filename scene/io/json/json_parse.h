#pragma once
// JSON text to nlohmann::json for the glTF and the project file, with errors a user can act on:
// a number beyond the range of a double (1e400) is `non-finite-value` naming where it is (a JSON
// path such as `nodes[0].translation[0]`), and no message carries the parser's exception ids.
#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

namespace glint {

// Throws FileError(file, "non-finite-value" | "invalid-json" | "json-too-deep", ...); objects and
// arrays may nest `maxDepth` levels.
nlohmann::json parseJsonText(std::string_view text, const std::string& file, int maxDepth);

} // namespace glint
