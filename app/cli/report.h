#pragma once
// The one place that prints errors and warnings in the contract's format:
//   glint: FILE: what is wrong
//   glint: warning: FILE: ...
// CLI output is never translated.
#include "scene/core/diagnostics.h"

#include <set>
#include <string>
#include <utility>

namespace glint::cli {

void printError(const std::string& message);
void printError(const std::string& file, const std::string& message);
void printWarning(const Warning& warning);

// Prints every warning; returns true when the command must fail because of them (--strict).
bool reportWarnings(const Warnings& warnings, bool strict);

// Renderer warnings (the GPU scene's: missing or undecodable textures, resampled sizes) name the
// texture but no file: they are printed under the scene file's name.
Warnings withFile(Warnings warnings, const std::string& file);

// Prints each distinct warning once per run, however many frames upload the same scene.
class WarningsOnce {
public:
    // Prints the warnings not printed yet. --strict: throws FileError naming `file` when there was
    // any, before the image is written (exit code 1, as for loader warnings).
    void report(const Warnings& warnings, const std::string& file, bool strict);

private:
    std::set<std::pair<std::string, std::string>> printed_; // (code, message)
};

} // namespace glint::cli
