#include "command.h"
#include "exit_codes.h"
#include "report.h"

#include "app/version.h"

#include "scene/core/diagnostics.h"

#include <exception>
#include <string>

namespace glint::cli {

namespace {

void configureParser(CLI::App& app, Action& action) {
    app.set_version_flag("--version", std::string("glint ") + kVersion);
    app.require_subcommand(1);
    app.fallthrough(false);
    addInfoCommand(app, action);
    addConvertCommand(app, action);
    addRenderCommand(app, action);
    addEncodeCommand(app, action);
    addBenchCommand(app, action);
}

// CLI11 messages are already specific ("The following argument was not expected: --x");
// the contract wants them on one line after "glint:".
int usageError(const CLI::ParseError& e) {
    std::string message = e.what();
    for (char& c : message)
        if (c == '\n') c = ' ';
    printError(message + " (see --help)");
    return kUsage;
}

} // namespace

int runCommandLine(int argc, char** argv) {
    Action action;
    CLI::App app{"Glint: scene editor and path tracer.\n"
                 "Without a subcommand, opens the editor (glint [FILE]).",
                 "glint"};
    configureParser(app, action);
    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& e) {
        return app.exit(e); // --help (of the subcommand it follows) or --version, on stdout
    } catch (const CLI::ParseError& e) {
        return usageError(e);
    }
    try {
        return action ? action() : kUsage;
    } catch (const FileError& e) {
        printError(e.file(), e.message());
    } catch (const std::exception& e) {
        printError(e.what());
    }
    return kFailure;
}

} // namespace glint::cli
