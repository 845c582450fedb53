#pragma once
// How a render's error against a converged reference is spread over its pixels: relMSE as
// docs/CLI.md defines it for `glint bench` (the mean over pixels and RGB of (x - r)^2 / (r^2 + 0.01)),
// and the share of that sum held by the worst 0.1 % of pixels, which fireflies dominate (a
// well-behaved estimator spreads its error: a few per cent there). Images are RGBA floats, rows
// in the same order; references are read from and written to EXR (RGB float) through OpenImageIO.
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace glint::test {

struct ErrorShare {
    double relMse = 0.0;
    double worstShare = 0.0;    // of the sum of per-pixel relMSE, in the worst `worstFraction` of pixels
    std::size_t worstPixels = 0;
    double meanLuminance = 0.0; // of the image (Rec. 709 weights)
    double referenceLuminance = 0.0;
};

// Per pixel: the mean over RGB of (x - r)^2 / (r^2 + 0.01).
inline std::vector<double> pixelRelMse(const std::vector<float>& image, const std::vector<float>& reference) {
    const std::size_t n = std::min(image.size(), reference.size()) / 4;
    std::vector<double> error(n, 0.0);
    for (std::size_t p = 0; p < n; ++p) {
        double e = 0.0;
        for (std::size_t c = 0; c < 3; ++c) {
            const double x = image[p * 4 + c], r = reference[p * 4 + c];
            e += (x - r) * (x - r) / (r * r + 0.01);
        }
        error[p] = e / 3.0;
    }
    return error;
}

inline double luminanceMean(const std::vector<float>& rgba) {
    double sum = 0.0;
    const std::size_t n = rgba.size() / 4;
    for (std::size_t p = 0; p < n; ++p) sum += 0.2126 * rgba[p * 4] + 0.7152 * rgba[p * 4 + 1] + 0.0722 * rgba[p * 4 + 2];
    return n > 0 ? sum / static_cast<double>(n) : 0.0;
}

inline ErrorShare errorShare(const std::vector<float>& image, const std::vector<float>& reference, double worstFraction = 0.001) {
    std::vector<double> error = pixelRelMse(image, reference);
    ErrorShare s;
    if (error.empty()) return s;
    double total = 0.0;
    for (const double e : error) total += e;
    s.worstPixels = std::max<std::size_t>(1, static_cast<std::size_t>(worstFraction * static_cast<double>(error.size())));
    std::partial_sort(error.begin(), error.begin() + static_cast<std::ptrdiff_t>(s.worstPixels), error.end(), std::greater<>());
    double worst = 0.0;
    for (std::size_t i = 0; i < s.worstPixels; ++i) worst += error[i];
    s.relMse = total / static_cast<double>(error.size());
    s.worstShare = total > 0.0 ? worst / total : 0.0;
    s.meanLuminance = luminanceMean(image);
    s.referenceLuminance = luminanceMean(reference);
    return s;
}

// An RGB(A) EXR as RGBA floats (A = 1), rows top-down; empty when it cannot be read.
inline std::vector<float> readExrRgba(const std::string& file, int& width, int& height) {
    auto in = OIIO::ImageInput::open(file);
    if (!in) return {};
    const OIIO::ImageSpec& spec = in->spec();
    width = spec.width;
    height = spec.height;
    const int channels = spec.nchannels;
    std::vector<float> pixels(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * static_cast<std::size_t>(channels));
    if (channels < 3 || !in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data())) return {};
    std::vector<float> rgba(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, 1.0f);
    for (std::size_t p = 0; p < rgba.size() / 4; ++p)
        for (std::size_t c = 0; c < 3; ++c) rgba[p * 4 + c] = pixels[p * static_cast<std::size_t>(channels) + c];
    return rgba;
}

// The RGB of an RGBA image as a float EXR (ZIP), rows top-down.
inline bool writeExrRgb(const std::string& file, const std::vector<float>& rgba, int width, int height) {
    auto out = OIIO::ImageOutput::create(file);
    if (!out) return false;
    OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::FLOAT);
    spec.attribute("compression", "zip");
    std::vector<float> rgb;
    rgb.reserve(rgba.size() / 4 * 3);
    for (std::size_t p = 0; p < rgba.size() / 4; ++p) rgb.insert(rgb.end(), {rgba[p * 4], rgba[p * 4 + 1], rgba[p * 4 + 2]});
    return out->open(file, spec) && out->write_image(OIIO::TypeDesc::FLOAT, rgb.data()) && out->close();
}

} // namespace glint::test
