#pragma once
// A render region: the part of the image the path tracer spends samples on (the viewport's
// Ctrl+B rectangle). Kept as fractions of the image, so it follows a resize or a resolution
// divisor proportionally. Outside it the last image stays as it was.
namespace glint::renderer {

struct RenderRegion {
    bool active = false;
    float x = 0.0f; // fractions of the image width and height, from its top-left corner
    float y = 0.0f;
    float width = 1.0f;
    float height = 1.0f;
    friend bool operator==(const RenderRegion&, const RenderRegion&) = default;
};

// Pixels as GL counts them: from the bottom-left corner.
struct PixelRect {
    int x = 0;
    int y = 0;
    int width = 0;
    int height = 0;
    friend bool operator==(const PixelRect&, const PixelRect&) = default;
};

// The pixels a region covers in a width x height image: every pixel the rectangle touches, at
// least one, never outside the image. An inactive region covers the whole image.
PixelRect regionPixels(const RenderRegion& region, int width, int height);

} // namespace glint::renderer
