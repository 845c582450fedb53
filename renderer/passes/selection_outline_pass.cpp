#include "renderer/passes/selection_outline_pass.h"

#include "renderer/passes/fullscreen_stage.h"
#include "renderer/passes/path_trace_pass.h"

#include <algorithm>

namespace glint::renderer {
namespace {

constexpr GLuint idsUnit = 1; // after the stage's G-buffer input

// Made or re-made at this size; RGBA8, whose fetches llvmpipe inlines.
void ensureTarget(std::optional<gl::RenderTarget>& target, int width, int height) {
    if (!target || target->width() != width || target->height() != height) target.emplace(width, height, std::vector<GLenum>{GL_RGBA8});
}

} // namespace

void SelectionOutlinePass::draw(const gl::RenderTarget& gbuffer, std::uint64_t idsVersion, std::vector<std::uint32_t> nodeIds,
                                unsigned int framebuffer, int width, int height) {
    if (nodeIds.empty() || width <= 0 || height <= 0) return;
    std::sort(nodeIds.begin(), nodeIds.end());
    // As the G-buffer holds them: node ids as floats, exact below 2^24.
    Key key{idsVersion, std::vector<float>(nodeIds.begin(), nodeIds.end()), gbuffer.width(), gbuffer.height(), width, height};
    if (drawn_ != key) {
        drawMask(gbuffer, key.sortedIds);
        drawLine(width, height);
        drawn_ = std::move(key);
    }
    const gl::ShaderProgram& program = programs_.get({"fullscreen.vert.glsl", "passes/selection_overlay.frag.glsl", {}, {"outColour"}});
    program.use();
    line_->bindTexture(0, 0, program.uniform("uLine"));
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glViewport(0, 0, width, height);
    triangle_.draw();
}

void SelectionOutlinePass::drawMask(const gl::RenderTarget& gbuffer, const std::vector<float>& sortedIds) {
    ensureTarget(mask_, gbuffer.width(), gbuffer.height());
    // The buffer only grows: uIdCount bounds the search.
    if (ids_ && ids_->texels() >= sortedIds.size()) ids_->update(0, sortedIds.data(), sortedIds.size());
    else ids_.emplace("the outlined-object buffer", GL_R32F, sortedIds.data(), sortedIds.size(), sizeof(float));
    const auto uniforms = [&](const gl::ShaderProgram& p) {
        glUniform1i(p.uniform("uIdCount"), static_cast<int>(sortedIds.size()));
        ids_->bind(idsUnit, p.uniform("uIds"));
    };
    runStage(programs_, triangle_, {"passes/selection_mask.frag.glsl", {"outMask"}, {{"uObjectId", gbuffer, objectIdAttachment}}, uniforms},
             *mask_);
}

void SelectionOutlinePass::drawLine(int width, int height) {
    ensureTarget(line_, width, height);
    const auto uniforms = [&](const gl::ShaderProgram& p) {
        glUniform2f(p.uniform("uImageFromOutput"), float(mask_->width()) / float(width), float(mask_->height()) / float(height));
        glUniform4f(p.uniform("uColour"), selectionColour.x, selectionColour.y, selectionColour.z, 1.0f);
    };
    runStage(programs_, triangle_, {"passes/selection_outline.frag.glsl", {"outColour"}, {{"uMask", *mask_, 0}}, uniforms}, *line_);
}

} // namespace glint::renderer
