#include "renderer/passes/accumulate_pass.h"

#include "renderer/passes/adaptive_sampling.h"
#include "renderer/passes/path_trace_pass.h"

namespace glint::renderer {

AccumulatePass::AccumulatePass(gl::ProgramCache& programs, int width, int height, GLuint stopTexture)
    : programs_(programs),
      targets_{makeAccumulationBuffer(width, height, stopTexture), makeAccumulationBuffer(width, height, stopTexture)} {}

gl::RenderTarget makeAccumulationBuffer(int width, int height, GLuint stopTexture) {
    static_assert(radianceSquaredAttachment == gBufferAttachmentCount);
    return gl::RenderTarget(width, height, std::vector<GLenum>(gBufferAttachmentCount + 1, GL_RGBA32F), stopTexture);
}

void AccumulatePass::add(const gl::RenderTarget& sample, bool cullStopped) {
    const gl::ShaderProgram& program = programs_.get({"fullscreen.vert.glsl", "passes/accumulate.frag.glsl", {},
                                                      {"outRadiance", "outAlbedo", "outNormalDepth", "outObjectId",
                                                       "outDiffuseAlbedo", "outSpecularAlbedo", "outSpecularRadiance",
                                                       "outRadianceSquared"}});
    const int previous = current_;
    const int next = 1 - current_;
    ++count_;
    program.use();
    glUniform1f(program.uniform("uSampleCount"), static_cast<float>(count_));
    const char* previousNames[] = {"uPreviousRadiance", "uPreviousAlbedo", "uPreviousNormalDepth", "uPreviousObjectId",
                                   "uPreviousDiffuseAlbedo", "uPreviousSpecularAlbedo", "uPreviousSpecularRadiance"};
    const char* sampleNames[] = {"uSampleRadiance", "uSampleAlbedo", "uSampleNormalDepth", "uSampleObjectId",
                                 "uSampleDiffuseAlbedo", "uSampleSpecularAlbedo", "uSampleSpecularRadiance"};
    for (int i = 0; i < gBufferAttachmentCount; ++i) {
        targets_[previous].bindTexture(i, static_cast<GLuint>(i), program.uniform(previousNames[i]));
        sample.bindTexture(i, static_cast<GLuint>(gBufferAttachmentCount + i), program.uniform(sampleNames[i]));
    }
    targets_[previous].bindTexture(radianceSquaredAttachment, 2 * gBufferAttachmentCount, program.uniform("uPreviousRadianceSquared"));
    targets_[next].bindForDrawing();
    const CullStoppedPixels cull(cullStopped);
    triangle_.draw();
    current_ = next;
}

} // namespace glint::renderer
