#pragma once
// Time-slicing of the viewport's path tracer: how much to render per frame and how many frames fit
// in one paint, so one paint stays within its GL budget (about 30 ms) and the event loop keeps
// answering. Pure arithmetic over measured frame times; tested without GL.
//
// Moving views render whole frames of the real-time configuration at a resolution divisor: a frame
// over the budget raises it by one step, a frame that would fit even one step finer lowers it, and
// moving views never go below half resolution.
// Still views always converge at full resolution: full-resolution samples are traced in bands of
// rows (as many as fit the budget, from the measured cost of a row), and until the first one is
// whole a low-resolution preview frame stands in, at the smallest divisor whose frame fits. Where a
// whole full-resolution frame fits, there are neither bands nor a preview.
#include <algorithm>
#include <cmath>

namespace glint::editor {

class FrameBudget {
public:
    explicit FrameBudget(double budgetMs = 30.0) : budgetMs_(budgetMs) {}

    // The moving view's divisor of the widget's size: 2 = half resolution.
    int movingDivisor() const { return moving_; }

    // Reports a moving frame (GL finished) rendered at `divisor`.
    void reportMoving(double ms, int divisor) {
        if (divisor != moving_) return; // a frame of an older setting says nothing about the current one
        if (ms > budgetMs_) moving_ = std::min(kMaxDivisor, moving_ + 1);
        else if (moving_ > kMinMovingDivisor && ms * double(moving_ * moving_) / double((moving_ - 1) * (moving_ - 1)) < 0.6 * budgetMs_)
            moving_ = moving_ - 1;
    }

    // The still view's preview divisor (1: no preview, a whole full-resolution frame fits).
    int previewDivisor(int height) const {
        if (msPerRow_ < 0.0) return kFirstPreviewDivisor;
        const double wholeFrame = msPerRow_ * double(std::max(1, height));
        if (wholeFrame <= kStillOverrun * budgetMs_) return 1;
        return std::clamp(int(std::ceil(std::sqrt(wholeFrame / (kFill * budgetMs_)))), 2, kMaxDivisor);
    }

    // Rows of a full-resolution band that fit the budget (at least one, at most the image).
    int rowsPerFrame(int height) const {
        height = std::max(1, height);
        if (msPerRow_ < 0.0) return std::max(1, height / kFirstBands);
        if (msPerRow_ * double(height) <= kStillOverrun * budgetMs_) return height;
        return std::clamp(int(kFill * budgetMs_ / std::max(msPerRow_, 1e-6)), 1, height);
    }

    // Reports a still preview frame of `rows` rows (at 1/divisor of the size, so each of its rows
    // costs 1/divisor of a full one, and there are 1/divisor as many).
    void reportPreview(double ms, int rows, int divisor) { noteRowCost(ms * double(divisor) / double(std::max(1, rows))); }
    // Reports a full-resolution band of `rows` rows.
    void reportRows(double ms, int rows) { noteRowCost(ms / double(std::max(1, rows))); }
    double msPerRow() const { return msPerRow_; } // < 0 until a still frame was measured

    // Whether another frame fits into this paint after `elapsedMs`, given the last frame took `lastMs`.
    bool anotherFits(double elapsedMs, double lastMs) const { return elapsedMs + lastMs <= budgetMs_; }
    double budgetMs() const { return budgetMs_; }
    void setBudgetMs(double ms) { budgetMs_ = ms; }

    static constexpr int kMaxDivisor = 8;
    static constexpr int kMinMovingDivisor = 2;
    static constexpr int kFirstPreviewDivisor = 4; // before anything was measured
    static constexpr int kFirstBands = 16;
    // A still frame may overrun the budget by this much before it is cut into bands: a few bands
    // cost more than one frame (each re-runs the whole-screen draw).
    static constexpr double kStillOverrun = 1.5;
    static constexpr double kFill = 0.8; // plan bands and previews to this share of the budget

private:
    // The cost of one full-resolution row, smoothed over the last few measures (frame times on a
    // shared machine vary by +-20 %).
    void noteRowCost(double ms) { msPerRow_ = msPerRow_ < 0.0 ? ms : 0.5 * (msPerRow_ + ms); }

    double budgetMs_;
    int moving_ = kMinMovingDivisor;
    double msPerRow_ = -1.0;
};

} // namespace glint::editor
