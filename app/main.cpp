// glint: the editor when run without a subcommand, the headless command line otherwise.
#include "cli/command.h"
#include "cli/exit_codes.h"
#include "cli/report.h"
#include "editor/main_window/editor_app.h"
#include "app/version.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace {

constexpr std::array<std::string_view, 5> kSubcommands{"info", "convert", "render", "bench", "encode"};

bool isSubcommand(std::string_view word) {
    return std::find(kSubcommands.begin(), kSubcommands.end(), word) != kSubcommands.end();
}

bool wantsCommandLine(int argc, char** argv) {
    if (argc < 2) return false;
    std::string_view first = argv[1];
    return first.starts_with("-") || isSubcommand(first);
}

// Edits (insert, delete, substitute, swap two neighbours) that turn a into b.
std::size_t editDistance(std::string_view a, std::string_view b) {
    std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
    for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i)
        for (std::size_t j = 1; j <= b.size(); ++j) {
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    return d[a.size()][b.size()];
}

// `glint rendr scene.gltf` must not open the editor on a file called "rendr": a first argument
// that is neither a subcommand nor an existing file is a usage error, with the nearest
// subcommand when one is close. Returns the exit code, or -1 when the editor may open.
int rejectUnknownFirstArgument(int argc, char** argv) {
    if (argc < 2) return -1;
    const std::string_view first = argv[1];
    std::error_code error;
    if (std::filesystem::exists(std::filesystem::path(std::string(first)), error)) return -1;
    std::string_view nearest;
    std::size_t best = 3; // at most two edits away
    for (const std::string_view name : kSubcommands)
        if (const std::size_t distance = editDistance(first, name); distance < best) {
            best = distance;
            nearest = name;
        }
    const std::string word(first);
    if (!nearest.empty())
        glint::cli::printError("unknown subcommand '" + word + "' (did you mean " + std::string(nearest) + "?)");
    else if (argc > 2)
        glint::cli::printError("unknown subcommand '" + word + "' (see --help)");
    else
        glint::cli::printError(word, "no such file, and not a subcommand (see --help)");
    return glint::cli::kUsage;
}

} // namespace

int main(int argc, char** argv) {
    if (wantsCommandLine(argc, argv)) return glint::cli::runCommandLine(argc, argv);
    if (const int code = rejectUnknownFirstArgument(argc, argv); code >= 0) return code;
    if (!glint::editor::haveDisplay()) {
        // Without a window system Qt would abort; point at what works instead.
        glint::cli::printError("no display for the editor (DISPLAY is not set); run it under xvfb-run, "
                               "or use a subcommand such as `glint info FILE` (glint --help)");
        return glint::cli::kUsage;
    }
    return glint::editor::runEditor(argc, argv, glint::kVersion);
}
