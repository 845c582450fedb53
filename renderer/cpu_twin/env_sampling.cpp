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
// longitude wrapping, latitude clamped at the poles (GL_REPEAT and GL_CLAMP_TO_EDGE). Along each
// axis the interpolation gives the pixel 3/4 of the weight and each neighbour 1/8 (9/16, 3/32 and
// 1/64 in 2D), so the filter runs as a row pass and a column pass. Weighting by the pixel alone
// left a dark pixel beside a bright one almost never sampled although half its area reads a good
// part of the bright one: radiance over pdf there reached 40 to 115 times its mean on real maps
// (fireflies on everything the map lights).
class BilinearMeans {
public:
    BilinearMeans(int width, int height, std::span<const float> rgb)
        : width_(width), height_(height), rgb_(rgb), luminance_(std::size_t(width)), above_(std::size_t(width)),
          here_(std::size_t(width)), below_(std::size_t(width)), means_(std::size_t(width)) {}

    // Row y's means; rows are asked for in order from 0.
    const std::vector<double>& row(int y) {
        if (y == 0) {
            filterRow(0, here_);
            above_ = here_; // above the top row: the top row again (clamped)
        } else {
            std::swap(above_, here_);
            std::swap(here_, below_);
        }
        filterRow(std::min(y + 1, height_ - 1), below_);
        for (std::size_t x = 0; x < means_.size(); ++x) means_[x] = 0.75 * here_[x] + 0.125 * (above_[x] + below_[x]);
        return means_;
    }

private:
    // Row y's luminance filtered along the row, wrapping.
    void filterRow(int y, std::vector<double>& out) {
        for (int x = 0; x < width_; ++x) luminance_[std::size_t(x)] = pixelLuminance(rgb_, y * width_ + x);
        for (int x = 0; x < width_; ++x) {
            const double left = luminance_[std::size_t(x == 0 ? width_ - 1 : x - 1)];
            const double right = luminance_[std::size_t(x == width_ - 1 ? 0 : x + 1)];
            out[std::size_t(x)] = 0.75 * luminance_[std::size_t(x)] + 0.125 * (left + right);
        }
    }

    int width_;
    int height_;
    std::span<const float> rgb_;
    std::vector<double> luminance_;
    std::vector<double> above_;
    std::vector<double> here_;
    std::vector<double> below_;
    std::vector<double> means_;
};

// The map's mean luminance over the sphere (each row weighted by its solid angle, sin(theta)).
double sphereMeanLuminance(int width, int height, std::span<const float> rgb) {
    double sum = 0.0, solidAngle = 0.0;
    for (int y = 0; y < height; ++y) {
        double row = 0.0;
        for (int x = 0; x < width; ++x) row += pixelLuminance(rgb, y * width + x);
        double sinTheta = std::sin(std::numbers::pi * (y + 0.5) / height);
        sum += row * sinTheta;
        solidAngle += width * sinTheta;
    }
    return sum / solidAngle;
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

    // MIS compensation (Karlik et al. 2019, "MIS Compensation"): light sampling is always weighted
    // against BSDF sampling, which finds the map's dim, even part well, so the table leaves out the
    // map's mean and light samples go to what stands out of it (the sun, the softboxes). An even map
    // keeps the uniform table below.
    const double mean = sphereMeanLuminance(width, height, rgb);
    BilinearMeans means(width, height, rgb);
    std::vector<double> rowWeights(static_cast<std::size_t>(height), 0.0);
    std::vector<double> columnWeights(static_cast<std::size_t>(width));
    bool anyLight = false;
    for (int y = 0; y < height; ++y) {
        double sinTheta = std::sin(std::numbers::pi * (y + 0.5) / height);
        const std::vector<double>& read = means.row(y);
        for (int x = 0; x < width; ++x) columnWeights[std::size_t(x)] = std::max(0.0, read[std::size_t(x)] - mean) * sinTheta;
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
