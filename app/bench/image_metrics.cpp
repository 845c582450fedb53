#include "image_metrics.h"

#include <algorithm>
#include <cmath>

namespace glint::bench {
namespace {

double srgbEncode(double v) {
    v = std::clamp(v, 0.0, 1.0);
    return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

std::vector<double> tonemappedLuminance(const std::vector<float>& rgba) {
    std::vector<double> out(rgba.size() / 4);
    for (std::size_t p = 0; p < out.size(); ++p) {
        const double y = std::max(0.0, 0.2126 * rgba[p * 4] + 0.7152 * rgba[p * 4 + 1] + 0.0722 * rgba[p * 4 + 2]);
        out[p] = srgbEncode(y / (1.0 + y));
    }
    return out;
}

// Separable Gaussian blur (11 taps, sigma 1.5), edges clamped.
std::vector<double> blur(const std::vector<double>& in, int width, int height) {
    double weights[11];
    double total = 0.0;
    for (int i = 0; i < 11; ++i) total += weights[i] = std::exp(-(i - 5) * (i - 5) / (2.0 * 1.5 * 1.5));
    for (double& w : weights) w /= total;
    const auto at = [&](const std::vector<double>& v, int x, int y) {
        return v[static_cast<std::size_t>(std::clamp(y, 0, height - 1)) * static_cast<std::size_t>(width) +
                 static_cast<std::size_t>(std::clamp(x, 0, width - 1))];
    };
    std::vector<double> rows(in.size()), out(in.size());
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            double s = 0.0;
            for (int i = 0; i < 11; ++i) s += weights[i] * at(in, x + i - 5, y);
            rows[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)] = s;
        }
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            double s = 0.0;
            for (int i = 0; i < 11; ++i) s += weights[i] * at(rows, x, y + i - 5);
            out[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)] = s;
        }
    return out;
}

} // namespace

double relMse(const std::vector<float>& image, const std::vector<float>& reference) {
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t p = 0; p * 4 < image.size(); ++p)
        for (std::size_t c = 0; c < 3; ++c) {
            const double x = image[p * 4 + c];
            const double r = reference[p * 4 + c];
            sum += (x - r) * (x - r) / (r * r + 0.01);
            ++count;
        }
    return count ? sum / static_cast<double>(count) : 0.0;
}

double ssim(const std::vector<float>& image, const std::vector<float>& reference, int width, int height) {
    const std::vector<double> a = tonemappedLuminance(image);
    const std::vector<double> b = tonemappedLuminance(reference);
    std::vector<double> aa(a.size()), bb(a.size()), ab(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        aa[i] = a[i] * a[i];
        bb[i] = b[i] * b[i];
        ab[i] = a[i] * b[i];
    }
    const auto muA = blur(a, width, height), muB = blur(b, width, height);
    const auto sAA = blur(aa, width, height), sBB = blur(bb, width, height), sAB = blur(ab, width, height);
    const double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;
    double sum = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const double varA = sAA[i] - muA[i] * muA[i], varB = sBB[i] - muB[i] * muB[i], cov = sAB[i] - muA[i] * muB[i];
        sum += (2 * muA[i] * muB[i] + c1) * (2 * cov + c2) / ((muA[i] * muA[i] + muB[i] * muB[i] + c1) * (varA + varB + c2));
    }
    return a.empty() ? 1.0 : sum / static_cast<double>(a.size());
}

} // namespace glint::bench
