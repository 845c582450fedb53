#pragma once
// What a video file is made with (docs/CLI.md, "glint encode"): H.264 in .mp4 (yuv420p, BT.709
// tags, CRF 18), ProRes 422 HQ in .mov (yuv422p10), FFV1 in .mkv (lossless 8-bit RGB). The
// encoder uses a fixed number of threads, because x264's output depends on it: the same frames
// give the same bytes on every machine with the same libraries.
#include <filesystem>
#include <optional>
#include <string>

namespace glint::video {

enum class Codec { H264, ProRes, Ffv1 };

struct VideoSettings {
    Codec codec = Codec::H264;
    int fpsNumerator = 24;
    int fpsDenominator = 1;
    int crf = 18;         // H.264 only
};

inline constexpr int kEncoderThreads = 2;

// "h264", "prores", "ffv1" (case-insensitive); throws std::invalid_argument.
Codec parseCodec(const std::string& name);
std::string codecName(Codec codec);
// The codec a container gets by default: .mp4 -> h264, .mov -> prores, .mkv -> ffv1; throws
// std::invalid_argument for other extensions.
Codec defaultCodecFor(const std::filesystem::path& file);
// Throws std::invalid_argument when the container cannot hold the codec (ProRes or FFV1 in .mp4).
void checkContainer(const std::filesystem::path& file, Codec codec);

} // namespace glint::video
