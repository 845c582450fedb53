#pragma once
// Frame numbers and times of an animation (docs/CLI.md, "Time and frame numbers"): frame k is at
// t0 + k / fps, fps possibly rational (24000/1001); --frames A-B is inclusive and 0-based.
#include "scene/core/scene.h"

#include <string>

namespace glint::cli {

struct Fps {
    int numerator = 24;
    int denominator = 1;
    double value() const { return double(numerator) / double(denominator); }
};

struct FrameRange {
    int first = 0;
    int last = 0; // inclusive
    int count() const { return last - first + 1; }
};

// "24", "29.97" is refused (ambiguous), "24000/1001"; throws std::invalid_argument.
Fps parseFps(const std::string& text);
// The highest frame number: 7 digits, 4.8 days at 24 fps. Bounded so that a range's count, the
// loops over its frames and the frame lists of a shard stay far from int overflow and fit memory.
constexpr int kMaxFrame = 9'999'999;

// "A-B" with 0 <= A <= B <= kMaxFrame, or a single "A"; throws std::invalid_argument.
FrameRange parseFrameRange(const std::string& text);

// Whether the scene has anything to animate: a camera path or a glTF animation.
bool hasAnimation(const Scene& scene);

// The default range: frame 0 at the timeline start to the last frame at or before the timeline
// end (or the animation's last key when the project sets no end), at `fps`. Throws
// std::invalid_argument when that last frame is beyond kMaxFrame.
FrameRange defaultFrameRange(const Scene& scene, const Fps& fps);

// t0 + k * denominator / numerator, computed so that every run gives the same double.
double frameTime(const Scene& scene, const Fps& fps, int frame);

} // namespace glint::cli
