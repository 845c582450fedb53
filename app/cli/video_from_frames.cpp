#include "video_from_frames.h"

#include "renderer/output/frame_check.h"
#include "renderer/output/video_encoder.h"
#include "renderer/output/video_frame_image.h"
#include "scene/core/diagnostics.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace glint::cli {

std::vector<std::pair<int, std::filesystem::path>> findFrames(const FramePattern& pattern,
                                                              const std::optional<FrameRange>& range) {
    const std::filesystem::path folder = pattern.folder.empty() ? std::filesystem::path(".") : pattern.folder;
    const std::string patternText = (pattern.folder / (pattern.prefix + std::string(std::size_t(pattern.digits), '#') + pattern.suffix)).string();
    std::vector<std::pair<int, std::filesystem::path>> frames;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
        const auto number = pattern.match(entry.path().filename().string());
        if (number && (!range || (*number >= range->first && *number <= range->last))) frames.emplace_back(*number, pattern.frame(*number));
    }
    if (ec) throw FileError(patternText, "no-folder", "cannot list the frames' folder: " + ec.message());
    if (frames.empty()) throw FileError(patternText, "no-frames", "no frames match this pattern");
    std::sort(frames.begin(), frames.end());
    const int first = range ? range->first : frames.front().first;
    const int last = range ? range->last : frames.back().first;
    int expected = first;
    for (const auto& [number, file] : frames) {
        if (number != expected) break;
        ++expected;
    }
    if (expected <= last)
        throw FileError(pattern.frame(expected).string(), "missing-frame",
                        "frame " + std::to_string(expected) + " of " + std::to_string(first) + "-" + std::to_string(last) + " is missing");
    return frames;
}

namespace {

Fps recordedFps(const std::filesystem::path& firstFrame) {
    const auto metadata = renderer::readGlintMetadata(firstFrame);
    const auto it = metadata.find("fps");
    if (it == metadata.end()) return {};
    try {
        return parseFps(it->second);
    } catch (const std::invalid_argument&) {
        return {};
    }
}

} // namespace

void encodeFrames(const FramePattern& pattern, const std::optional<FrameRange>& range, const std::optional<Fps>& fps,
                  const std::string& out, const std::optional<std::string>& codec) {
    const auto start = std::chrono::steady_clock::now();
    video::VideoSettings settings;
    settings.codec = codec ? video::parseCodec(*codec) : video::defaultCodecFor(out);
    video::checkContainer(out, settings.codec);
    const auto frames = findFrames(pattern, range);
    const Fps rate = fps.value_or(recordedFps(frames.front().second));
    settings.fpsNumerator = rate.numerator;
    settings.fpsDenominator = rate.denominator;

    const video::Rgba8Image first = video::loadFrameForVideo(frames.front().second);
    video::VideoEncoder encoder(out, settings, first.width, first.height);
    encoder.addFrame(first.pixels);
    for (std::size_t i = 1; i < frames.size(); ++i) {
        const video::Rgba8Image image = video::loadFrameForVideo(frames[i].second);
        if (image.width != first.width || image.height != first.height)
            throw FileError(frames[i].second.string(), "frame-size", "the frame's size differs from the first frame's");
        encoder.addFrame(image.pixels);
    }
    encoder.finish();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::fprintf(stderr, "glint: wrote %s (%zu frames, %dx%d, %s, %d/%d fps) in %.2f s\n", out.c_str(), frames.size(),
                 encoder.codedWidth(), encoder.codedHeight(), video::codecName(settings.codec).c_str(), rate.numerator,
                 rate.denominator, seconds);
}

} // namespace glint::cli
