#include "chi_square.h"

#include <cmath>

namespace glint::twin::test {
namespace {

// Upper tail of the chi-square distribution through the Wilson-Hilferty cube-root normal
// approximation (accurate to a few per cent of p for the tens of degrees of freedom used here).
double chiSquareUpperTail(double statistic, int dof) {
    if (dof <= 0) return 1.0;
    double k = dof;
    double z = (std::cbrt(statistic / k) - (1.0 - 2.0 / (9.0 * k))) / std::sqrt(2.0 / (9.0 * k));
    return 0.5 * std::erfc(z / std::sqrt(2.0));
}

} // namespace

ChiSquareResult chiSquareTest(const std::vector<double>& observed, const std::vector<double>& expected,
                              double minExpected) {
    ChiSquareResult result;
    double pooledObserved = 0.0;
    double pooledExpected = 0.0;
    int cells = 0;
    for (std::size_t i = 0; i < observed.size(); ++i) {
        if (expected[i] <= 0.0 && observed[i] > 0.0) {
            result.pValue = 0.0;
            result.message = "cell " + std::to_string(i) + " expects nothing but got " +
                             std::to_string(observed[i]) + " samples";
            return result;
        }
        if (expected[i] < minExpected) {
            pooledObserved += observed[i];
            pooledExpected += expected[i];
            continue;
        }
        result.statistic += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
        ++cells;
    }
    if (pooledExpected > 0.0) {
        result.statistic += (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / pooledExpected;
        ++cells;
    }
    result.degreesOfFreedom = cells - 1;
    result.pValue = chiSquareUpperTail(result.statistic, result.degreesOfFreedom);
    result.message = "chi2 = " + std::to_string(result.statistic) + ", dof = " +
                     std::to_string(result.degreesOfFreedom) + ", p = " + std::to_string(result.pValue);
    return result;
}

double sidakSignificance(double alpha, int testCount) { return 1.0 - std::pow(1.0 - alpha, 1.0 / testCount); }

} // namespace glint::twin::test
