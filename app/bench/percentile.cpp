#include "percentile.h"

#include <algorithm>
#include <cstddef>

namespace glint::bench {

double percentile(std::vector<double> values, double q) {
    std::sort(values.begin(), values.end());
    const double index = q * static_cast<double>(values.size() - 1);
    const auto low = static_cast<std::size_t>(index);
    const std::size_t high = std::min(low + 1, values.size() - 1);
    return values[low] + (values[high] - values[low]) * (index - static_cast<double>(low));
}

} // namespace glint::bench
