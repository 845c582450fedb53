#pragma once
// Exposure and a tone curve over linear radiance, sRGB-encoded in the shader into an RGBA8 target.
// Rounding to 8 bits is the GL fixed-point conversion (round to nearest of value x 255).
#include "renderer/gl/fullscreen_triangle.h"
#include "renderer/gl/program_cache.h"
#include "renderer/gl/render_target.h"
#include "scene/core/settings.h"

namespace glint::renderer {

class TonemapPass {
public:
    explicit TonemapPass(gl::ProgramCache& programs) : programs_(programs) {}
    // Reads attachment 0 of `radiance`; draws into attachment 0 of `target`.
    void render(const gl::RenderTarget& radiance, float exposureEv, Tonemapper tonemapper, const gl::RenderTarget& target);

private:
    gl::ProgramCache& programs_;
    gl::FullscreenTriangle triangle_;
};

} // namespace glint::renderer
