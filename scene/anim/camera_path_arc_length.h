#pragma once
// Arc length of a camera path's position curve, and its inverse for the constant-speed mode.
// Each segment is split into a fixed number of equal time steps, each integrated with 5-point
// Gauss-Legendre quadrature into a monotone cumulative table (deterministic: no adaptivity that
// depends on rounding). Inversion finds the step by binary search, then refines the time with
// safeguarded Newton steps on the exact integral, so the speed comes out constant to far better
// than 1 %.
#include "camera_path_hermite.h"

#include <vector>

namespace glint {

class ArcLengthTable {
public:
    // Needs at least two keys; `keys` must outlive the table.
    explicit ArcLengthTable(const std::vector<CameraKey>& keys);

    double totalLength() const { return lengths_.back(); }
    // The path time at which the travelled distance is `distance` (clamped to [0, totalLength]).
    double timeAtDistance(double distance) const;

private:
    double lengthBetween(double from, double to) const;
    double speedAt(double t) const;

    const std::vector<CameraKey>& keys_;
    std::vector<double> times_;   // step boundaries, first key to last key
    std::vector<double> lengths_; // distance travelled at each boundary
};

} // namespace glint
