#pragma once
// Writes frames into a video file through libavformat/libavcodec, converting RGBA8 sRGB with
// libswscale (BT.709 matrix, limited range, tagged BT.709). Frames whose width or height is odd
// are padded by one pixel (the last column/row repeated), since 4:2:0 and 4:2:2 need even sizes.
#include "renderer/output/video_settings.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

namespace glint::video {

class VideoEncoder {
public:
    // Opens `file` (written under a temporary name until finish()); throws FileError.
    VideoEncoder(const std::filesystem::path& file, const VideoSettings& settings, int width, int height);
    ~VideoEncoder(); // without finish(): the temporary file is removed
    VideoEncoder(const VideoEncoder&) = delete;
    VideoEncoder& operator=(const VideoEncoder&) = delete;

    // `rgba`: width x height RGBA8, rows top-down, the size given at construction.
    void addFrame(const std::vector<std::uint8_t>& rgba);
    // Flushes the encoder, writes the trailer and renames the file into place.
    void finish();

    int codedWidth() const;
    int codedHeight() const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

} // namespace glint::video
