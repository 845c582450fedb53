#pragma once
// The error measures of docs/CLI.md ("glint bench"): relMSE = mean over pixels and channels of
// (x - r)^2 / (r^2 + 0.01); SSIM on tonemapped luminance (Y / (1 + Y), sRGB-encoded) with an 11x11
// Gaussian window, sigma 1.5. Images are RGBA floats, rows in any order (both the same).
#include <vector>

namespace glint::bench {

double relMse(const std::vector<float>& image, const std::vector<float>& reference);
double ssim(const std::vector<float>& image, const std::vector<float>& reference, int width, int height);

} // namespace glint::bench
