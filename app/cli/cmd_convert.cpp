// glint convert IN OUT: any supported scene format to glTF (.gltf + .bin, or .glb).
#include "command.h"
#include "exit_codes.h"
#include "report.h"
#include "scene_file.h"

#include "renderer/output/image_files.h"

#include <algorithm>
#include <cctype>

namespace glint::cli {

namespace {

struct ConvertOptions {
    std::string input;
    std::string output;
    bool strict = false;
};

int runConvert(const ConvertOptions& o) {
    LoadResult loaded = openSceneFile(o.input);
    if (reportWarnings(loaded.warnings, o.strict)) return kFailure;
    // The project's environment image resolves in the input's folder: copied beside OUT like textures.
    renderer::prepareOutputFolder(o.output);
    SaveOptions save;
    save.sourceFolder = std::filesystem::absolute(o.input).parent_path();
    SaveReport report = saveScene(loaded.scene, o.output, save);
    if (reportWarnings(report.dropped, o.strict)) return kFailure;
    return kSuccess;
}

std::string checkOutputName(const std::string& out) {
    std::string ext = std::filesystem::path(out).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext == ".gltf" || ext == ".glb" ? std::string() : "OUT must end in .gltf or .glb: " + out;
}

} // namespace

void addConvertCommand(CLI::App& app, Action& action) {
    auto options = std::make_shared<ConvertOptions>();
    CLI::App* cmd = app.add_subcommand("convert", "Convert a scene (glTF, GLB, OBJ, PLY, STL, FBX, DAE, 3DS) to "
                                                  "glTF. Writes the project file beside OUT as well.");
    cmd->add_option("IN", options->input, "Input scene")->required();
    cmd->add_option("OUT", options->output, "Output .gltf (with .bin and images beside it) or .glb")
        ->required()
        ->check(CLI::Validator(checkOutputName, "FILE.gltf|FILE.glb", "gltf-or-glb"));
    cmd->add_flag("--strict", options->strict, "Treat warnings as failures (default: off)");
    cmd->callback([options, &action] { action = [options] { return runConvert(*options); }; });
}

} // namespace glint::cli
