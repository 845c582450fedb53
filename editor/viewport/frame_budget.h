#pragma once
// Time-slicing of the viewport's path tracer: how much of the view to render per frame and how
// many frames fit in one paint, so one paint stays within its GL budget (about 30 ms) and the
// event loop keeps answering. Pure arithmetic over measured frame times; tested without GL.
#include <algorithm>

namespace glint::editor {

class FrameBudget {
public:
    explicit FrameBudget(double budgetMs = 30.0) : budgetMs_(budgetMs) {}

    // The divisor of the widget's size for the next frames: 1 = full resolution. Moving views
    // render at least at half resolution; a still view drops to lower ones only while a frame at
    // the current one would overrun the budget.
    int resolutionDivisor(bool moving) const { return std::max(moving ? 2 : 1, divisor_); }

    // Reports a measured frame (GL finished) at `divisor`; adapts the divisor for the next ones.
    void report(double ms, int divisor) {
        // Pixel count scales with 1/divisor^2: estimate the full-resolution cost.
        const double fullMs = ms * divisor * divisor;
        fullMs_ = fullMs_ <= 0.0 ? fullMs : 0.7 * fullMs_ + 0.3 * fullMs;
        int d = 1;
        while (d < kMaxDivisor && fullMs_ / (d * d) > budgetMs_) ++d;
        divisor_ = d;
    }

    // Whether another frame fits into this paint after `elapsedMs`, given the last frame took `lastMs`.
    bool anotherFits(double elapsedMs, double lastMs) const { return elapsedMs + lastMs <= budgetMs_; }

    double estimatedMs(int divisor) const { return fullMs_ / (divisor * divisor); }
    double budgetMs() const { return budgetMs_; }

    static constexpr int kMaxDivisor = 8;

private:
    double budgetMs_;
    double fullMs_ = 0.0;
    int divisor_ = 1;
};

} // namespace glint::editor
