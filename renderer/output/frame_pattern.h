#pragma once
// Output names for animation frames (docs/CLI.md, "Time and frame numbers"): one run of '#' in the
// file name stands for the absolute frame number, zero-padded to at least that many digits.
// "frames/shot_####.exr" -> "frames/shot_0007.exr", frame 12345 -> "frames/shot_12345.exr".
#include <filesystem>
#include <optional>
#include <string>

namespace glint::renderer {

struct FramePattern {
    std::filesystem::path folder;
    std::string prefix; // file-name text before the '#' run
    std::string suffix; // file-name text after it, extension included
    int digits = 0;     // length of the '#' run

    std::filesystem::path frame(int number) const;
    // The frame number when `fileName` (no folder) is a name this pattern makes, else nullopt.
    // Temporary files (".shot_0001.partial-123.exr") never match: they start with a dot.
    std::optional<int> match(const std::string& fileName) const;
};

// Throws std::invalid_argument when the file name has no '#' run, or more than one.
FramePattern parseFramePattern(const std::filesystem::path& pattern);

// True when the file name holds a '#': --animation needs a pattern, a still must not have one.
bool hasFramePlaceholder(const std::filesystem::path& path);

} // namespace glint::renderer
