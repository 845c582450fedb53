#pragma once
// CDF tables for importance sampling an equirectangular environment in proportion to
// luminance * sin(theta) (the sin accounts for the rows' shrinking solid angle), each pixel's
// luminance being its mean as the renderer reads the map (bilinear, so a pixel shares its
// neighbours' light) less the map's mean over the sphere (MIS compensation: light samples of the
// map are always weighted against BSDF samples, which find its even part). The layout is what
// shaders/sampling/distribution.glsl reads from a one-channel float texture (GL_R32F):
// rows 0..height-1 hold each image row's conditional CDF over its columns (width + 1 values),
// row `height` the marginal CDF over rows (height + 1 values); unused texels are 0.
#include <span>
#include <vector>

namespace glint::twin {

struct EnvironmentSamplingTable {
    int imageWidth = 0;
    int imageHeight = 0;
    int tableWidth = 0;  // max(imageWidth, imageHeight) + 1
    int tableHeight = 0; // imageHeight + 1
    std::vector<float> cdf; // tableWidth * tableHeight, row-major, row 0 = top image row
};

// `rgb` is linear RGB, width * height * 3 floats, row 0 at the top (v = 0). Negative or non-finite
// values count as black; an all-black or even image gets weights sin(theta), i.e. uniform on the
// sphere.
EnvironmentSamplingTable buildEnvironmentSamplingTable(int width, int height, std::span<const float> rgb);

} // namespace glint::twin
