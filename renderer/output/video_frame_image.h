#pragma once
// A rendered frame as 8-bit sRGB RGBA, ready for a video: PNG/JPEG/TIFF as stored, EXR through
// the display transform its metadata records (glint:tonemap, glint:exposureEv; ACES and 0 EV for
// EXRs from elsewhere), as the PNG of the same render would be.
#include <cstdint>
#include <filesystem>
#include <vector>

namespace glint::video {

struct Rgba8Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels; // rows top-down, RGBA
};

// Throws FileError naming the file when it cannot be read.
Rgba8Image loadFrameForVideo(const std::filesystem::path& file);

} // namespace glint::video
