#pragma once
// One full-screen stage of a pass: a fragment shader, its named texture inputs, its uniforms and
// the target it draws. Every reconstruction stage is one call of this (Falcor's FullScreenPass).
#include "renderer/gl/fullscreen_triangle.h"
#include "renderer/gl/program_cache.h"
#include "renderer/gl/render_target.h"

#include <functional>
#include <string>
#include <vector>

namespace glint::renderer {

struct StageInput {
    const char* uniform;
    const gl::RenderTarget& target;
    int attachment = 0;
};

struct Stage {
    std::string fragmentFile;                 // under shaders/, e.g. "reconstruction/taa.frag.glsl"
    std::vector<std::string> outputs;         // fragment outputs, bound to attachments in order
    std::vector<StageInput> inputs;           // bound to texture units 0, 1, ... in order
    std::function<void(const gl::ShaderProgram&)> uniforms; // may be empty
    gl::Defines defines = {};                 // the fragment shader's variant
};

void runStage(gl::ProgramCache& programs, const gl::FullscreenTriangle& triangle, const Stage& stage,
              const gl::RenderTarget& output);

} // namespace glint::renderer
