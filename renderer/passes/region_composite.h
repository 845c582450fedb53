#pragma once
// The image a render region shows: the last full image outside the region (frozen when the
// region is set or moved) and the running result inside it, copied in after every frame. The
// passes run under a scissor, so only the region's pixels of their targets are up to date; this
// keeps the rest of the picture as it was instead of showing those stale pixels. It outlives the
// frame targets: after a resize (or a moving view's coarser resolution) the last image is scaled.
#include "renderer/gl/render_target.h"
#include "renderer/render_region.h"

#include <memory>

namespace glint::renderer {

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
