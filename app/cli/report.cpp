#include "report.h"

#include <cstdio>

namespace glint::cli {

void printError(const std::string& message) { std::fprintf(stderr, "glint: %s\n", message.c_str()); }

void printError(const std::string& file, const std::string& message) {
    std::fprintf(stderr, "glint: %s: %s\n", file.c_str(), message.c_str());
}

void printWarning(const Warning& w) {
    std::fprintf(stderr, "glint: warning: %s: %s [%s]\n", w.file.c_str(), w.message.c_str(), w.code.c_str());
}

bool reportWarnings(const Warnings& warnings, bool strict) {
    for (const auto& w : warnings) printWarning(w);
    if (strict && !warnings.empty()) {
        printError("--strict: " + std::to_string(warnings.size()) + " warning(s) treated as errors");
        return true;
    }
    return false;
}

} // namespace glint::cli
