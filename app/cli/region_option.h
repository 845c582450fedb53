#pragma once
// --region X,Y,W,H of `glint render`: only these pixels of the output image are rendered. Pixels
// of the output image (--size), counted from its top-left corner as image files store rows; one
// convention only (no fractions), so a region means the same pixels in every tool that reads them.
#include "renderer/render_region.h"

#include <string>

namespace glint::cli {

using renderer::ImageWindow;

// Parses "X,Y,W,H": four integers, X, Y >= 0, W, H >= 1. Throws std::invalid_argument saying what
// is wrong (CLI11 prefixes the option's name).
ImageWindow parseRegion(const std::string& text);

// Throws std::invalid_argument when `region` does not lie wholly inside a width x height image.
void checkRegionInside(const ImageWindow& region, int width, int height);

// "X,Y,W,H", as the metadata records it.
std::string formatRegion(const ImageWindow& region);

} // namespace glint::cli
