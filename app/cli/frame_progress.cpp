#include "frame_progress.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace glint::cli {

std::string formatDuration(double seconds) {
    const long total = long(std::lround(std::max(0.0, seconds)));
    char buf[32];
    if (total >= 3600) std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", total / 3600, total / 60 % 60, total % 60);
    else std::snprintf(buf, sizeof buf, "%ld:%02ld", total / 60, total % 60);
    return buf;
}

FrameProgress::FrameProgress(int framesToRender) : total_(framesToRender) {}

void FrameProgress::skipped(int frame, const std::string& file) {
    ++done_;
    std::fprintf(stderr, "glint: frame %d (%d/%d) kept: %s is complete with the same settings\n", frame, done_, total_,
                 file.c_str());
}

void FrameProgress::rendered(int frame, const std::string& file) {
    ++done_;
    ++rendered_;
    // Skipped frames cost nothing, so the rate is per rendered frame since the start.
    const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
    const double perFrame = elapsed / rendered_;
    std::fprintf(stderr, "glint: frame %d (%d/%d) wrote %s, %.2f s/frame, ETA %s\n", frame, done_, total_, file.c_str(),
                 perFrame, formatDuration(perFrame * (total_ - done_)).c_str());
}

} // namespace glint::cli
