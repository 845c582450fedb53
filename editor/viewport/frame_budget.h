#pragma once
// Time-slicing of the viewport's path tracer: how much of the view to render per frame and how
// many frames fit in one paint, so one paint stays within its GL budget (about 30 ms) and the
// event loop keeps answering. Pure arithmetic over measured frame times; tested without GL.
//
// Moving and still views keep separate resolution divisors (they run different configurations):
// a frame over the budget raises the divisor by one step, a frame that would fit even one step
// finer lowers it. Moving views never go below half resolution. Still frames may run up to 1.5x
// the budget before the divisor rises, since every change of it restarts accumulation.
#include <algorithm>

namespace glint::editor {

class FrameBudget {
public:
    explicit FrameBudget(double budgetMs = 30.0) : budgetMs_(budgetMs) {}

    // The divisor of the widget's size: 1 = full resolution.
    int resolutionDivisor(bool moving) const { return moving ? moving_ : still_; }

    // Reports a frame (GL finished) rendered at `divisor`.
    void report(double ms, int divisor, bool moving) {
        int& d = moving ? moving_ : still_;
        const int minimum = moving ? kMinMovingDivisor : 1;
        const double limit = moving ? budgetMs_ : 1.5 * budgetMs_;
        if (divisor != d) return; // a frame of an older setting says nothing about the current one
        if (ms > limit) d = std::min(kMaxDivisor, d + 1);
        else if (d > minimum && ms * double(d * d) / double((d - 1) * (d - 1)) < 0.6 * budgetMs_) d = d - 1;
    }

    // Whether another frame fits into this paint after `elapsedMs`, given the last frame took `lastMs`.
    bool anotherFits(double elapsedMs, double lastMs) const { return elapsedMs + lastMs <= budgetMs_; }
    double budgetMs() const { return budgetMs_; }

    static constexpr int kMaxDivisor = 8;
    static constexpr int kMinMovingDivisor = 2;

private:
    double budgetMs_;
    int moving_ = kMinMovingDivisor;
    int still_ = 1;
};

} // namespace glint::editor
