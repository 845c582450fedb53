#include "renderer/passes/motion_pass.h"

#include "renderer/passes/path_trace_pass.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

namespace glint::renderer {
namespace {

constexpr GLuint movedUnit = 3; // after the stage's three G-buffer inputs

// Records sorted by id, as motion.frag.glsl searches them: the id, then the matrix's columns. One
// zero texel when nothing moved (a buffer texture cannot be empty).
std::vector<glm::vec4> movedTexels(std::vector<MovedInstance> moved) {
    std::sort(moved.begin(), moved.end(), [](const MovedInstance& a, const MovedInstance& b) { return a.objectId < b.objectId; });
    std::vector<glm::vec4> texels;
    texels.reserve(moved.size() * 5 + 1);
    for (const MovedInstance& m : moved) {
        texels.push_back({m.objectId, 0.0f, 0.0f, 0.0f});
        for (int column = 0; column < 4; ++column) texels.push_back(m.previousFromCurrent[column]);
    }
    if (texels.empty()) texels.emplace_back(0.0f);
    return texels;
}

} // namespace

MotionPass::MotionPass(gl::ProgramCache& programs, int width, int height)
    : programs_(programs), motion_(width, height, {GL_RGBA32F}) {}

const gl::RenderTarget& MotionPass::execute(const gl::RenderTarget& gbuffer, const CameraSetup& camera,
                                            const CameraSetup& previousCamera, const std::vector<MovedInstance>& moved) {
    const std::vector<glm::vec4> texels = movedTexels(moved);
    // The buffer only grows: frames rewrite it in place (uMovedCount bounds the search).
    if (moved_ && moved_->texels() >= texels.size()) moved_->update(0, texels.data(), texels.size());
    else moved_.emplace("the moved-instance buffer", GL_RGBA32F, texels.data(), texels.size(), sizeof(glm::vec4));
    const auto uniforms = [&](const gl::ShaderProgram& p) {
        const glm::mat4 previousCameraFromWorld = glm::inverse(previousCamera.worldFromCamera);
        glUniform2f(p.uniform("uResolution"), static_cast<float>(motion_.width()), static_cast<float>(motion_.height()));
        glUniformMatrix4fv(p.uniform("uWorldFromCamera"), 1, GL_FALSE, glm::value_ptr(camera.worldFromCamera));
        glUniform2f(p.uniform("uHalfExtent"), camera.halfExtent.x, camera.halfExtent.y);
        glUniform1i(p.uniform("uOrthographic"), camera.orthographic ? 1 : 0);
        glUniformMatrix4fv(p.uniform("uPreviousCameraFromWorld"), 1, GL_FALSE, glm::value_ptr(previousCameraFromWorld));
        glUniform2f(p.uniform("uPreviousHalfExtent"), previousCamera.halfExtent.x, previousCamera.halfExtent.y);
        glUniform1i(p.uniform("uPreviousOrthographic"), previousCamera.orthographic ? 1 : 0);
        glUniform1i(p.uniform("uMovedCount"), static_cast<int>(moved.size()));
        moved_->bind(movedUnit, p.uniform("uMoved"));
    };
    runStage(programs_, triangle_,
             {"reconstruction/motion.frag.glsl", {"outMotion"},
              {{"uNormalDepth", gbuffer, normalDepthAttachment},
               {"uObjectId", gbuffer, objectIdAttachment},
               {"uSpecularRadiance", gbuffer, specularRadianceAttachment}},
              uniforms},
             motion_);
    return motion_;
}

} // namespace glint::renderer
