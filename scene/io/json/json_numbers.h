#pragma once
// Locale-independent, shortest round-trip numbers and deterministic JSON text for Glint's files.
//
// A float is written as the shortest decimal that reads back as the same float (0.1f -> "0.1", not
// "0.10000000149011612"): jsonFloat() stores the double nearest to that decimal, and
// deterministicJsonText() prints every double as its own shortest round-trip decimal with
// std::to_chars, which never consults the C or C++ locale (no "0,5" under de_DE).
#include <nlohmann/json.hpp>

#include <span>
#include <string>

namespace glint {

// The double nearest to f's shortest float decimal; non-finite values become JSON null.
nlohmann::json jsonFloat(float f);
nlohmann::json jsonFloats(std::span<const float> values);

// Text with object keys sorted (nlohmann::json keeps objects ordered by key), `indent` spaces per
// level (negative: compact, one line), numbers by std::to_chars (-0 as 0), strings escaped as JSON
// requires.
std::string deterministicJsonText(const nlohmann::json& value, int indent);

// Adds the members of `unknown` that `target` lacks, verbatim (objects merged key by key): how
// content Glint does not interpret is written back. Keys Glint wrote itself win.
void mergeUnknown(nlohmann::json& target, const nlohmann::json& unknown);

} // namespace glint
