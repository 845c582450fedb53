#include "renderer/output/video_settings.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace glint::video {

namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

} // namespace

Codec parseCodec(const std::string& name) {
    const std::string n = lower(name);
    if (n == "h264") return Codec::H264;
    if (n == "prores") return Codec::ProRes;
    if (n == "ffv1") return Codec::Ffv1;
    throw std::invalid_argument("unknown codec '" + name + "' (use h264, prores or ffv1)");
}

std::string codecName(Codec codec) {
    switch (codec) {
    case Codec::H264: return "h264";
    case Codec::ProRes: return "prores";
    case Codec::Ffv1: break;
    }
    return "ffv1";
}

Codec defaultCodecFor(const std::filesystem::path& file) {
    const std::string ext = lower(file.extension().string());
    if (ext == ".mp4") return Codec::H264;
    if (ext == ".mov") return Codec::ProRes;
    if (ext == ".mkv") return Codec::Ffv1;
    throw std::invalid_argument("unsupported video container '" + ext + "' (use .mp4, .mov or .mkv)");
}

void checkContainer(const std::filesystem::path& file, Codec codec) {
    if (defaultCodecFor(file) == Codec::H264 && codec != Codec::H264)
        throw std::invalid_argument(".mp4 holds H.264 only; use .mov for prores, .mkv for ffv1");
}

} // namespace glint::video
