#include "camera_path_arc_length.h"

#include <algorithm>
#include <array>

namespace glint {

namespace {

constexpr int kStepsPerSegment = 64;
constexpr int kNewtonSteps = 4;

// 5-point Gauss-Legendre nodes and weights on [-1, 1].
constexpr std::array<double, 5> kNodes{0.0, -0.5384693101056831, 0.5384693101056831, -0.9061798459386640,
                                       0.9061798459386640};
constexpr std::array<double, 5> kWeights{0.5688888888888889, 0.4786286704993665, 0.4786286704993665,
                                         0.2369268850561891, 0.2369268850561891};

glm::dvec3 positionOf(const CameraKey& key) { return key.position; }

} // namespace

ArcLengthTable::ArcLengthTable(const std::vector<CameraKey>& keys) : keys_(keys) {
    times_.push_back(keys.front().time);
    lengths_.push_back(0.0);
    for (std::size_t k = 0; k + 1 < keys.size(); ++k)
        for (int step = 1; step <= kStepsPerSegment; ++step) {
            const double t = step == kStepsPerSegment
                                 ? keys[k + 1].time
                                 : keys[k].time + (keys[k + 1].time - keys[k].time) * step / kStepsPerSegment;
            lengths_.push_back(lengths_.back() + lengthBetween(times_.back(), t));
            times_.push_back(t);
        }
}

double ArcLengthTable::speedAt(double t) const {
    return glm::length(hermiteDerivative(keys_, findPathSegment(keys_, t), positionOf));
}

// Within one table step the curve is one polynomial piece, so Gauss-Legendre is accurate.
double ArcLengthTable::lengthBetween(double from, double to) const {
    const double half = 0.5 * (to - from);
    const double mid = 0.5 * (to + from);
    double sum = 0.0;
    for (std::size_t i = 0; i < kNodes.size(); ++i) sum += kWeights[i] * speedAt(mid + half * kNodes[i]);
    return sum * half;
}

double ArcLengthTable::timeAtDistance(double distance) const {
    distance = std::clamp(distance, 0.0, totalLength());
    const auto above = std::upper_bound(lengths_.begin() + 1, lengths_.end() - 1, distance);
    const std::size_t step = std::size_t(above - lengths_.begin()) - 1;
    double low = times_[step], high = times_[step + 1];
    const double stepLength = lengths_[step + 1] - lengths_[step];
    if (stepLength <= 0.0) return low;
    double t = low + (high - low) * (distance - lengths_[step]) / stepLength;
    for (int i = 0; i < kNewtonSteps; ++i) {
        const double error = lengths_[step] + lengthBetween(times_[step], t) - distance;
        (error > 0.0 ? high : low) = t;
        const double speed = speedAt(t);
        const double next = speed > 0.0 ? t - error / speed : 0.5 * (low + high);
        t = (next >= low && next <= high) ? next : 0.5 * (low + high); // stay inside the bracket
    }
    return t;
}

} // namespace glint
