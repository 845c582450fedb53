#pragma once
// What the export dialogs ask for, as plain data. No renderer (GL) headers here: Qt's moc
// compiles this into one unit with Qt's GL headers, and epoxy must never follow those.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace glint::editor {

struct ExportSettings {
    std::filesystem::path sceneFile;  // the document's file: metadata and the environment folder
    std::filesystem::path out;        // a still's file, or an animation's pattern with one '#' run
    int width = 640;
    int height = 360;
    int spp = 64;
    std::string configuration = "accumulate";
    std::uint32_t seed = 0;
    std::string camera;               // empty: the project's active camera
    std::string aovs = "all";         // EXR layers, as --aovs
    std::string passes;               // EXR render passes, as --passes; empty: none
    std::optional<double> time;       // a still at this time (as --time); unset: the scene as it is
    bool animation = false;
    int firstFrame = 0;
    int lastFrame = 0;
    int fpsNumerator = 24;
    int fpsDenominator = 1;
    // An animation also encoded into this video (.mp4, .mov, .mkv) by `glint encode`, which
    // `encoder` names (the editor passes its own executable); empty: frames only.
    std::filesystem::path video;
    std::filesystem::path encoder;
};

} // namespace glint::editor
