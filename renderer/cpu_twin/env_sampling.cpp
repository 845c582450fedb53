#include "renderer/cpu_twin/env_sampling.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace glint::twin {
namespace {

double pixelWeight(std::span<const float> rgb, int index) {
    double y = 0.2126 * rgb[3 * index] + 0.7152 * rgb[3 * index + 1] + 0.0722 * rgb[3 * index + 2];
    return std::isfinite(y) && y > 0.0 ? y : 0.0;
}

// Writes the normalised running sum of `weights` into cdf[0..n]; uniform when all weights are 0.
void writeCdf(const std::vector<double>& weights, float* cdf) {
    const auto n = weights.size();
    double total = 0.0;
    for (double w : weights) total += w;
    double running = 0.0;
    cdf[0] = 0.0f;
    for (std::size_t i = 0; i < n; ++i) {
        running += weights[i];
        cdf[i + 1] = total > 0.0 ? static_cast<float>(running / total) : static_cast<float>(double(i + 1) / double(n));
    }
    cdf[n] = 1.0f; // exact, whatever the rounding of the sum
}

} // namespace

EnvironmentSamplingTable buildEnvironmentSamplingTable(int width, int height, std::span<const float> rgb) {
    if (width <= 0 || height <= 0 || rgb.size() != std::size_t(width) * std::size_t(height) * 3)
        throw std::invalid_argument("environment sampling table: image size does not match its pixels");
    EnvironmentSamplingTable table;
    table.imageWidth = width;
    table.imageHeight = height;
    table.tableWidth = std::max(width, height) + 1;
    table.tableHeight = height + 1;
    table.cdf.assign(std::size_t(table.tableWidth) * std::size_t(table.tableHeight), 0.0f);

    std::vector<double> rowWeights(static_cast<std::size_t>(height), 0.0);
    std::vector<double> columnWeights(static_cast<std::size_t>(width));
    bool anyLight = false;
    for (int y = 0; y < height; ++y) {
        double sinTheta = std::sin(std::numbers::pi * (y + 0.5) / height);
        for (int x = 0; x < width; ++x) columnWeights[std::size_t(x)] = pixelWeight(rgb, y * width + x) * sinTheta;
        writeCdf(columnWeights, &table.cdf[std::size_t(y) * std::size_t(table.tableWidth)]);
        for (double w : columnWeights) rowWeights[std::size_t(y)] += w;
        anyLight = anyLight || rowWeights[std::size_t(y)] > 0.0;
    }
    if (!anyLight) {
        for (int y = 0; y < height; ++y) rowWeights[std::size_t(y)] = std::sin(std::numbers::pi * (y + 0.5) / height);
    }
    writeCdf(rowWeights, &table.cdf[std::size_t(height) * std::size_t(table.tableWidth)]);
    return table;
}

} // namespace glint::twin
