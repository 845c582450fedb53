// glint: the editor when run without a subcommand, the headless command line otherwise.
#include "cli/command.h"
#include "cli/exit_codes.h"
#include "cli/report.h"
#include "editor/main_window/editor_app.h"
#include "app/version.h"

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
    if (!glint::editor::haveDisplay()) {
        // Without a window system Qt would abort; point at what works instead.
        glint::cli::printError("no display for the editor (DISPLAY is not set); run it under xvfb-run, "
                               "or use a subcommand such as `glint info FILE` (glint --help)");
        return glint::cli::kUsage;
    }
    return glint::editor::runEditor(argc, argv, glint::kVersion);
}
