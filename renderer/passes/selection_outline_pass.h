#pragma once
// The outline of chosen objects (the editor's selection) over a shown image, found from the first
// hits' object ids of the G-buffer that image came from: a mask at the image's size
// (shaders/passes/selection_mask.frag.glsl: 1 on the objects' pixels), a line along the mask's
// edges at the output's size (selection_outline.frag.glsl), kept while the ids, the objects and the
// sizes stay the same, then copied over the caller's framebuffer where it is drawn
// (selection_overlay.frag.glsl). Display only: no sample and no history depends on it. On llvmpipe
// at 1280x720 the mask and the line took about 17 ms and the copy 6 ms (a paint without the outline:
// 22 ms); while the ids stay (an accumulating view after its first sample) a paint redraws only the
// copy.
#include "renderer/gl/fullscreen_triangle.h"
#include "renderer/gl/program_cache.h"
#include "renderer/gl/render_target.h"
#include "renderer/gl/texture_buffer.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <vector>

namespace glint::renderer {

// The colour that marks the selection, in the path-traced view and the raster preview alike.
inline constexpr glm::vec3 selectionColour{1.0f, 0.62f, 0.16f};

class SelectionOutlinePass {
public:
    explicit SelectionOutlinePass(gl::ProgramCache& programs) : programs_(programs) {}
    // Outlines the objects `nodeIds` (any order; none: nothing is drawn) as `gbuffer`'s objectId
    // attachment sees them, into `framebuffer` (the caller's, bound for drawing afterwards) at
    // width x height. `idsVersion` changes whenever the G-buffer's ids may have changed.
    void draw(const gl::RenderTarget& gbuffer, std::uint64_t idsVersion, std::vector<std::uint32_t> nodeIds, unsigned int framebuffer,
              int width, int height);

private:
    struct Key {
        std::uint64_t idsVersion = 0;
        std::vector<float> sortedIds;
        int imageWidth = 0, imageHeight = 0, width = 0, height = 0;
        friend bool operator==(const Key&, const Key&) = default;
    };
    void drawMask(const gl::RenderTarget& gbuffer, const std::vector<float>& sortedIds);
    void drawLine(int width, int height);

    gl::ProgramCache& programs_;
    gl::FullscreenTriangle triangle_;
    std::optional<gl::RenderTarget> mask_;
    std::optional<gl::RenderTarget> line_; // at the output's size: the colour where the line is, alpha 0 elsewhere
    std::optional<gl::TextureBuffer> ids_;
    std::optional<Key> drawn_; // what line_ holds
};

} // namespace glint::renderer
