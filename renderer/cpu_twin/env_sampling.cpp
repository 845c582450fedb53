#include "renderer/cpu_twin/env_sampling.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace glint::twin {
namespace {

double pixelLuminance(std::span<const float> rgb, int index) {
    double y = 0.2126 * rgb[3 * index] + 0.7152 * rgb[3 * index + 1] + 0.0722 * rgb[3 * index + 2];
    return std::isfinite(y) && y > 0.0 ? y : 0.0;
}

// The mean over pixel (x, y) of the image as the renderer reads it: bilinear between pixel centres,
// longitude wrapping, latitude clamped at the poles (GL_REPEAT and GL_CLAMP_TO_EDGE). Over a pixel,
// the interpolation gives the pixel 9/16 of the weight, each edge neighbour 3/32 and each corner
// neighbour 1/64. Weighting by the pixel alone left a dark pixel beside a bright one almost never
// sampled although half its area reads a good part of the bright one: radiance over pdf there was
// 40 times the mean on a studio map's softboxes (fireflies on everything the map lights).
std::vector<double> pixelWeights(int width, int height, std::span<const float> rgb) {
    std::vector<double> luminance(std::size_t(width) * std::size_t(height));
    for (int i = 0; i < width * height; ++i) luminance[std::size_t(i)] = pixelLuminance(rgb, i);
    const auto at = [&](int x, int y) {
        x = (x % width + width) % width;
        y = std::clamp(y, 0, height - 1);
        return luminance[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    };
    std::vector<double> weights(luminance.size());
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            double edges = at(x - 1, y) + at(x + 1, y) + at(x, y - 1) + at(x, y + 1);
            double corners = at(x - 1, y - 1) + at(x + 1, y - 1) + at(x - 1, y + 1) + at(x + 1, y + 1);
            weights[std::size_t(y) * std::size_t(width) + std::size_t(x)] = (9.0 / 16.0) * at(x, y) + (3.0 / 32.0) * edges + (1.0 / 64.0) * corners;
        }
    }
    return weights;
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

    const std::vector<double> weights = pixelWeights(width, height, rgb);
    std::vector<double> rowWeights(static_cast<std::size_t>(height), 0.0);
    std::vector<double> columnWeights(static_cast<std::size_t>(width));
    bool anyLight = false;
    for (int y = 0; y < height; ++y) {
        double sinTheta = std::sin(std::numbers::pi * (y + 0.5) / height);
        for (int x = 0; x < width; ++x) columnWeights[std::size_t(x)] = weights[std::size_t(y) * std::size_t(width) + std::size_t(x)] * sinTheta;
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
