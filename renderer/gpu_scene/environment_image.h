#pragma once
// An equirectangular environment image read through OpenImageIO as linear float RGB, row 0 at the
// top of the image (docs/UNITS.md, "Environment"). A cube map (a cross or a strip of six faces,
// environment_cube.h) is read into the same form.
#include <filesystem>
#include <vector>

namespace glint::renderer {

struct EnvironmentImage {
    int width = 0;
    int height = 0;
    std::vector<float> rgb; // width * height * 3
};

// Throws glint::FileError naming the file when it cannot be read.
EnvironmentImage loadEnvironmentImage(const std::filesystem::path& file);

} // namespace glint::renderer
