#include "renderer/passes/motion_pass.h"

#include "renderer/passes/path_trace_pass.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

namespace glint::renderer {

MotionPass::MotionPass(gl::ProgramCache& programs, int width, int height)
    : programs_(programs), motion_(width, height, {GL_RGBA32F}) {}

const gl::RenderTarget& MotionPass::execute(const gl::RenderTarget& gbuffer, const CameraSetup& camera,
                                            const CameraSetup& previousCamera, const std::vector<MovedInstance>& moved) {
    const auto uniforms = [&](const gl::ShaderProgram& p) {
        const glm::mat4 previousCameraFromWorld = glm::inverse(previousCamera.worldFromCamera);
        glUniform2f(p.uniform("uResolution"), static_cast<float>(motion_.width()), static_cast<float>(motion_.height()));
        glUniformMatrix4fv(p.uniform("uWorldFromCamera"), 1, GL_FALSE, glm::value_ptr(camera.worldFromCamera));
        glUniform2f(p.uniform("uHalfExtent"), camera.halfExtent.x, camera.halfExtent.y);
        glUniform1i(p.uniform("uOrthographic"), camera.orthographic ? 1 : 0);
        glUniformMatrix4fv(p.uniform("uPreviousCameraFromWorld"), 1, GL_FALSE, glm::value_ptr(previousCameraFromWorld));
        glUniform2f(p.uniform("uPreviousHalfExtent"), previousCamera.halfExtent.x, previousCamera.halfExtent.y);
        glUniform1i(p.uniform("uPreviousOrthographic"), previousCamera.orthographic ? 1 : 0);
        const int count = std::min(static_cast<int>(moved.size()), maxMovedInstances);
        std::vector<float> ids;
        std::vector<float> matrices;
        for (int i = 0; i < count; ++i) {
            ids.push_back(moved[static_cast<std::size_t>(i)].objectId);
            const float* m = glm::value_ptr(moved[static_cast<std::size_t>(i)].previousFromCurrent);
            matrices.insert(matrices.end(), m, m + 16);
        }
        glUniform1i(p.uniform("uMovedCount"), count);
        if (count > 0) {
            glUniform1fv(p.uniform("uMovedIds"), count, ids.data());
            glUniformMatrix4fv(p.uniform("uPreviousFromCurrent"), count, GL_FALSE, matrices.data());
        }
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
