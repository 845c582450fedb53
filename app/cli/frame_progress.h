#pragma once
// Progress of an animation on stderr: one line per frame (farm logs are files, so no '\r'),
// with the mean time per rendered frame and the time left at that rate.
#include <chrono>
#include <string>

namespace glint::cli {

class FrameProgress {
public:
    explicit FrameProgress(int framesToRender);
    void skipped(int frame, const std::string& file);  // kept by --resume
    void rendered(int frame, const std::string& file); // written
    int renderedCount() const { return rendered_; }

private:
    using Clock = std::chrono::steady_clock;
    int total_;
    int done_ = 0;
    int rendered_ = 0;
    Clock::time_point start_ = Clock::now();
};

// "1:02:03" / "2:03" for a duration in seconds (ETA display).
std::string formatDuration(double seconds);

} // namespace glint::cli
