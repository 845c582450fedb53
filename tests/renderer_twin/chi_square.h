#pragma once
// Pearson's chi-square goodness-of-fit test as pbrt and Mitsuba use it for sampling routines:
// cells with too small an expected count are pooled, and the p-value is compared with a
// Sidak-corrected significance level.
#include <string>
#include <vector>

namespace glint::twin::test {

struct ChiSquareResult {
    double statistic = 0.0;
    int degreesOfFreedom = 0;
    double pValue = 1.0;
    std::string message; // what failed, for the test log
};

// observed and expected counts per cell (same length). Cells expecting fewer than `minExpected`
// are pooled into one; a cell that expects nothing yet observes samples fails outright.
ChiSquareResult chiSquareTest(const std::vector<double>& observed, const std::vector<double>& expected,
                              double minExpected = 5.0);

// Significance for one of `testCount` independent tests so that all together keep `alpha`.
double sidakSignificance(double alpha, int testCount);

} // namespace glint::twin::test
