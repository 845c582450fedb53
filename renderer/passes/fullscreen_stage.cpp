#include "renderer/passes/fullscreen_stage.h"

namespace glint::renderer {

void runStage(gl::ProgramCache& programs, const gl::FullscreenTriangle& triangle, const Stage& stage,
              const gl::RenderTarget& output) {
    const gl::ShaderProgram& program = programs.get({"fullscreen.vert.glsl", stage.fragmentFile, stage.defines, stage.outputs});
    program.use();
    GLuint unit = 0;
    for (const StageInput& input : stage.inputs)
        input.target.bindTexture(input.attachment, unit++, program.uniform(input.uniform));
    if (stage.uniforms) stage.uniforms(program);
    output.bindForDrawing();
    triangle.draw();
}

} // namespace glint::renderer
