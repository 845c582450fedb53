#include "renderer/passes/tonemap_pass.h"

#include <cmath>

namespace glint::renderer {
namespace {

int shaderCode(Tonemapper tonemapper) {
    switch (tonemapper) {
    case Tonemapper::AcesFitted: return 1;
    case Tonemapper::PbrNeutral: return 2;
    case Tonemapper::None: break;
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
