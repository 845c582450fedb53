#include "renderer/passes/tonemap_pass.h"

#include <cmath>

namespace glint::renderer {
namespace {

// The shader's codes (tonemap.frag.glsl): the enum's order.
int shaderCode(Tonemapper tonemapper) {
    switch (tonemapper) {
    case Tonemapper::None: return 0;
    case Tonemapper::AcesFitted: return 1;
    case Tonemapper::PbrNeutral: return 2;
    case Tonemapper::AgX: return 3;
    case Tonemapper::Reinhard: return 4;
    case Tonemapper::Hable: return 5;
    }
    return 0;
}

} // namespace

void TonemapPass::render(const gl::RenderTarget& radiance, float exposureEv, Tonemapper tonemapper,
                         const gl::RenderTarget& target) {
    const gl::ShaderProgram& program = programs_.get({"fullscreen.vert.glsl", "passes/tonemap.frag.glsl", {}, {"outColor"}});
    program.use();
    radiance.bindTexture(0, 0, program.uniform("uRadiance"));
    glUniform1f(program.uniform("uExposureScale"), std::exp2(exposureEv));
    glUniform1i(program.uniform("uTonemapper"), shaderCode(tonemapper));
    target.bindForDrawing();
    triangle_.draw();
}

} // namespace glint::renderer
