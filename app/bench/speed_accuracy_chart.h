#pragma once
// The speed-vs-accuracy chart of `glint bench`: relMSE against time (log axes), one curve per
// configuration, written as PNG and SVG through Qt Charts. Needs a QApplication (the bench creates
// one on Qt's offscreen platform).
#include <string>
#include <vector>

namespace glint::bench {

struct ChartPoint {
    double ms = 0.0;     // cumulative render time up to this frame
    double relmse = 0.0;
};

struct ChartCurve {
    std::string name;
    std::vector<ChartPoint> points;
};

// Throws std::runtime_error when a file cannot be written.
void writeSpeedAccuracyChart(const std::vector<ChartCurve>& curves, const std::string& title,
                             const std::string& pngPath, const std::string& svgPath);

} // namespace glint::bench
