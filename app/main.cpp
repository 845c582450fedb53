// glint: the editor when run without a subcommand, the headless command line otherwise.
#include "cli/command.h"
#include "cli/exit_codes.h"
#include "cli/report.h"

#include <cstring>
#include <string_view>

namespace {

bool wantsCommandLine(int argc, char** argv) {
    if (argc < 2) return false;
    std::string_view first = argv[1];
    return first.starts_with("-") || first == "info" || first == "convert" || first == "render" ||
           first == "bench" || first == "encode";
}

} // namespace

int main(int argc, char** argv) {
    if (wantsCommandLine(argc, argv)) return glint::cli::runCommandLine(argc, argv);
    // The editor is not part of this build yet; say so instead of pretending.
    glint::cli::printError("the editor is not available in this build; use a subcommand (glint --help)");
    return glint::cli::kUsage;
}
