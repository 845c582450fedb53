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
// The still view's filter (denoise) of each new mean runs in steps of rows too, from the measured
// cost of a row of its stages: on a slow GL one filtering costs a few frames.
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

    // The still view's preview divisor (1: no preview, a whole full-resolution frame fits). With
    // `denoiseRows` > 0 (the rows of a whole filtering of the mean), the frame and its filtering:
    // where they do not fit one paint, the filtered preview stands in until the first filtered
    // mean is shown (the raw first sample would flash for a paint or more).
    int previewDivisor(int height, int denoiseRows = 0) const {
        if (msPerRow_ < 0.0) return kFirstPreviewDivisor;
        double firstImage = msPerRow_ * double(std::max(1, height));
        if (denoiseRows > 0 && msPerDenoiseRow_ > 0.0) firstImage += msPerDenoiseRow_ * double(denoiseRows);
        if (firstImage <= kStillOverrun * budgetMs_) return 1;
        return std::clamp(int(std::ceil(std::sqrt(firstImage / (kFill * budgetMs_)))), 2, kMaxDivisor);
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

    // Rows of the filter's stages that fit the budget (at least one).
    int denoiseRowsPerFrame(int height) const {
        if (msPerDenoiseRow_ < 0.0) return std::max(1, std::max(1, height) / kFirstBands);
        return std::max(1, int(kFill * budgetMs_ / std::max(msPerDenoiseRow_, 1e-6)));
    }
    // Reports a step of the filter over `rows` rows of its stages.
    void reportDenoiseRows(double ms, int rows) { smooth(msPerDenoiseRow_, ms / double(std::max(1, rows))); }
    double msPerDenoiseRow() const { return msPerDenoiseRow_; } // < 0 until a step was measured

    // The planned cost of the next still frame of an image `height` rows high: a step of the filter
    // or a band (a whole frame where it fits); 0 while that cost is unmeasured.
    double plannedMs(int height, bool denoiseStep) const {
        if (denoiseStep) return msPerDenoiseRow_ < 0.0 ? 0.0 : msPerDenoiseRow_ * denoiseRowsPerFrame(height);
        return msPerRow_ < 0.0 ? 0.0 : msPerRow_ * rowsPerFrame(height);
    }
    // Whether another frame fits into this paint after `elapsedMs`, given the last frame took
    // `lastMs` and the next is planned to take `plannedMs` (a short last step of the filter says
    // little of the band after it).
    bool anotherFits(double elapsedMs, double lastMs, double plannedMs = 0.0) const {
        return elapsedMs + std::max(lastMs, plannedMs) <= budgetMs_;
    }
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
    void noteRowCost(double ms) { smooth(msPerRow_, ms); }
    static void smooth(double& cost, double ms) { cost = cost < 0.0 ? ms : 0.5 * (cost + ms); }

    double budgetMs_;
    int moving_ = kMinMovingDivisor;
    double msPerRow_ = -1.0;
    double msPerDenoiseRow_ = -1.0;
};

} // namespace glint::editor
