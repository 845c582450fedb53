#pragma once
// Order statistics of timings: the benchmarks quote medians and spreads, never means, because the
// machines they run on are shared and a few slow frames would move a mean.
#include <vector>

namespace glint::bench {

// The q-quantile (0 <= q <= 1) with linear interpolation between order statistics; q = 0.5 is the
// median (the mean of the middle two for an even count). `values` must not be empty.
double percentile(std::vector<double> values, double q);

} // namespace glint::bench
