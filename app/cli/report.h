#pragma once
// The one place that prints errors and warnings in the contract's format:
//   glint: FILE: what is wrong
//   glint: warning: FILE: ...
// CLI output is never translated.
#include "scene/core/diagnostics.h"

#include <string>

namespace glint::cli {

void printError(const std::string& message);
void printError(const std::string& file, const std::string& message);
void printWarning(const Warning& warning);

// Prints every warning; returns true when the command must fail because of them (--strict).
bool reportWarnings(const Warnings& warnings, bool strict);

} // namespace glint::cli
