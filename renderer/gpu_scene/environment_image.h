#pragma once
// An equirectangular environment image read through OpenImageIO as linear float RGB, row 0 at the
// top of the image (docs/UNITS.md, "Environment"). A cube map (a cross or a strip of six faces,
// environment_cube.h) is read into the same form. CPU only (library glint_renderer_image).
#include "scene/io/image_decoder.h"

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace glint::renderer {

struct EnvironmentImage {
    int width = 0;
    int height = 0;
    std::vector<float> rgb; // width * height * 3
};

// Throws glint::FileError naming the file when it cannot be read, or when its header declares more
// than `limits` allow (checked before the pixels are allocated; the message names the limit).
EnvironmentImage loadEnvironmentImage(const std::filesystem::path& file, const DecodeLimits& limits = {});

// The same from an image file's bytes (PNG, JPEG, Radiance HDR, OpenEXR, TIFF); `name` names them in errors.
EnvironmentImage decodeEnvironmentImage(std::span<const std::uint8_t> encoded, const std::string& name,
                                        const DecodeLimits& limits = {});

} // namespace glint::renderer
