#include "frame_timing.h"

#include "scene/anim/node_animation.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace glint::cli {

namespace {

int parseCount(std::string_view text, const std::string& whole, const char* what) {
    int value = -1;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size() || value < 0)
        throw std::invalid_argument(std::string("expected ") + what + ", got '" + whole + "'");
    return value;
}

} // namespace

Fps parseFps(const std::string& text) {
    const std::size_t slash = text.find('/');
    Fps fps;
    fps.numerator = parseCount(std::string_view(text).substr(0, slash), text, "frames per second as N or N/D");
    fps.denominator = slash == std::string::npos
                          ? 1
                          : parseCount(std::string_view(text).substr(slash + 1), text, "frames per second as N or N/D");
    if (fps.numerator == 0 || fps.denominator == 0)
        throw std::invalid_argument("frames per second must be positive, got '" + text + "'");
    return fps;
}

FrameRange parseFrameRange(const std::string& text) {
    const std::size_t dash = text.find('-');
    const char* what = "a frame range A-B with 0 <= A <= B";
    FrameRange range;
    range.first = parseCount(std::string_view(text).substr(0, dash), text, what);
    range.last = dash == std::string::npos ? range.first : parseCount(std::string_view(text).substr(dash + 1), text, what);
    if (range.last < range.first) throw std::invalid_argument(std::string("expected ") + what + ", got '" + text + "'");
    if (range.last > kMaxFrame)
        throw std::invalid_argument("frame numbers go up to " + std::to_string(kMaxFrame) + ", got '" + text + "'");
    return range;
}

bool hasAnimation(const Scene& scene) {
    if (!scene.animations.empty()) return true;
    for (const auto& [id, node] : scene.nodes())
        if (const auto* camera = node.get<Camera>(); camera && !camera->path.empty()) return true;
    return false;
}

FrameRange defaultFrameRange(const Scene& scene, const Fps& fps) {
    const Timeline& timeline = scene.settings.timeline;
    const double end = timeline.end > timeline.start ? timeline.end : sceneAnimationTimeSpan(scene).second;
    const double frames = std::max(0.0, end - timeline.start) * fps.value();
    // A last key exactly on a frame time is that frame, despite rounding (1e-6 of a frame).
    const double last = std::floor(frames + 1e-6);
    // The project file bounds neither end nor start: a last frame beyond kMaxFrame (or not a number)
    // would not fit the int it becomes.
    if (!(last <= double(kMaxFrame))) {
        char text[32];
        std::snprintf(text, sizeof text, "%g", last);
        throw std::invalid_argument("the timeline's end is frame " + std::string(text) + " at " + std::to_string(fps.numerator) + "/" +
                                    std::to_string(fps.denominator) + " fps, beyond the last frame number " +
                                    std::to_string(kMaxFrame) + ": choose the frames with --frames");
    }
    return {0, static_cast<int>(last)};
}

double frameTime(const Scene& scene, const Fps& fps, int frame) {
    return scene.settings.timeline.start + double(frame) * double(fps.denominator) / double(fps.numerator);
}

} // namespace glint::cli
