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

Warnings withFile(Warnings warnings, const std::string& file) {
    for (Warning& w : warnings)
        if (w.file.empty()) w.file = file;
    return warnings;
}

void WarningsOnce::report(const Warnings& warnings, const std::string& file, bool strict) {
    std::size_t fresh = 0;
    for (const Warning& w : withFile(warnings, file)) {
        if (!printed_.insert({w.code, w.message}).second) continue;
        printWarning(w);
        ++fresh;
    }
    if (strict && fresh > 0)
        throw FileError(file, "strict", "--strict: " + std::to_string(fresh) + " renderer warning(s) treated as errors");
}

} // namespace glint::cli
