#pragma once
// The image a render region shows: the last full image outside the region (frozen when the
// region is set or moved) and the running result inside it, copied in after every frame. The
// passes run under a scissor, so only the region's pixels of their targets are up to date; this
// keeps the rest of the picture as it was instead of showing those stale pixels. It outlives the
// frame targets: after a resize (or a moving view's coarser resolution) the last image is scaled.
#include "renderer/configuration.h"
#include "renderer/gl/render_target.h"
#include "renderer/render_region.h"

#include <memory>

namespace glint::renderer {

// How far (pixels) the real-time reconstruction of one frame reads the path-traced samples around
// a pixel: TAA's 3x3 neighbourhood (1), the a-trous steps 2^i over 5x5 taps (2 (2^N - 1); each
// step's 3x3 variance blur lies inside), SVGF's 7x7 variance estimate (3), and anti-lag's strata
// (3: the 2x2 nearest 3x3 strata) or SVGF's 3x3 firefly test (1) at reprojection. Path tracing
// this margin around a region makes the region's first frame after a reset exactly the full
// frame's; later frames differ only through history, far inside the filters' weight tails. Every
// real-time configuration also reads the filtered still mean it fades into (76 px).
// Accumulate and Reference read no neighbours: 0.
int reconstructionReach(const ConfigurationTraits& traits, int svgfIterations);

class RegionComposite {
public:
    // Starts a new composite of width x height from `last` (linear radiance in attachment 0), or
    // where there is none from the previous composite, scaled to the new size; else black.
    void freeze(const gl::RenderTarget* last, int width, int height);
    bool fits(int width, int height) const;
    // Copies `rect` of `result`'s attachment 0 into the composite.
    void update(const gl::RenderTarget& result, const PixelRect& rect);
    const gl::RenderTarget& image() const { return *composite_; }
    void clear() { composite_.reset(); } // no region any more: nothing to keep

private:
    std::unique_ptr<gl::RenderTarget> composite_;
};

} // namespace glint::renderer
