#pragma once
// The mapping between time and x on the timeline ruler, and frame snapping at the project fps.
// Pure arithmetic, tested without widgets.
#include <algorithm>
#include <cmath>

namespace glint::editor {

struct TimeRange {
    double start = 0.0;
    double end = 5.0;
    double span() const { return std::max(1e-9, end - start); }
};

// x in [left, left + width] <-> time in [range.start, range.end].
inline double timeAtX(const TimeRange& range, double x, double left, double width) {
    return range.start + (x - left) / std::max(1.0, width) * range.span();
}
inline double xAtTime(const TimeRange& range, double t, double left, double width) {
    return left + (t - range.start) / range.span() * std::max(1.0, width);
}
// The time of the nearest frame (t0 + k / fps) to t.
inline double snapToFrame(double t, double t0, double fps) {
    return fps > 0.0 ? t0 + std::round((t - t0) * fps) / fps : t;
}

} // namespace glint::editor
