#include "renderer/passes/render_passes_pass.h"

#include "renderer/passes/adaptive_sampling.h"
#include "renderer/passes/fullscreen_stage.h"
#include "renderer/passes/path_trace_pass.h"

namespace glint::renderer {

namespace {

gl::RenderTarget makeMean(int width, int height) {
    return gl::RenderTarget(width, height, std::vector<GLenum>(renderPassesMeanTargets, GL_RGBA32F));
}

} // namespace

RenderPassesMean::RenderPassesMean(gl::ProgramCache& programs, int width, int height)
    : programs_(programs), targets_{makeMean(width, height), makeMean(width, height)} {}

void RenderPassesMean::add(const gl::RenderTarget& sample, int count, GLuint stopTexture) {
    static_assert(objectIdAttachment + renderPassesMeanTargets == renderPassesAttachmentCount);
    const gl::RenderTarget& previous = targets_[current_];
    const int next = 1 - current_;
    Stage stage{"passes/render_passes_mean.frag.glsl",
                {"outPass0", "outPass1", "outPass2", "outPass3", "outPass4"},
                {{"uPrevious0", previous, 0},
                 {"uPrevious1", previous, 1},
                 {"uPrevious2", previous, 2},
                 {"uPrevious3", previous, 3},
                 {"uPrevious4", previous, 4},
                 {"uSample0", sample, objectIdAttachment},
                 {"uSample1", sample, diffuseAlbedoAttachment},
                 {"uSample2", sample, specularAlbedoAttachment},
                 {"uSample3", sample, specularRadianceAttachment},
                 {"uSample4", sample, glossyIndirectAttachment}},
                [count, stopTexture](const gl::ShaderProgram& p) {
                    glUniform1f(p.uniform("uSampleCount"), static_cast<float>(count));
                    if (stopTexture) bindStopTexture(stopTexture, 10, p); // after the ten inputs' units
                }};
    if (stopTexture) stage.defines["ADAPTIVE_STOPS"] = "";
    runStage(programs_, triangle_, stage, targets_[next]);
    current_ = next;
}

} // namespace glint::renderer
