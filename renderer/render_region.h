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

// Pixels as image files count them: from the top-left corner (EXR's data window, the command
// line's --region). A separate type, so the two row orders never mix unnoticed.
struct ImageWindow {
    int x = 0;
    int y = 0;
    int width = 0;
    int height = 0;
    friend bool operator==(const ImageWindow&, const ImageWindow&) = default;
};

// The pixels a region covers in a width x height image: every pixel the rectangle touches, at
// least one, never outside the image. An inactive region covers the whole image.
PixelRect regionPixels(const RenderRegion& region, int width, int height);

// The same pixels counted from the other corner, in an image `height` rows high.
ImageWindow imageWindowOf(const PixelRect& rect, int height);
PixelRect pixelRectOf(const ImageWindow& window, int height);

// A region that covers exactly `window`'s pixels (regionPixels gives them back): its edges lie a
// quarter pixel inside the window's, so float rounding of the fractions never adds or drops a row.
RenderRegion regionOfWindow(const ImageWindow& window, int width, int height);

// `rect` grown by `margin` pixels on every side, clipped to the width x height image.
PixelRect grown(const PixelRect& rect, int margin, int width, int height);

} // namespace glint::renderer
