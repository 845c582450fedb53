#pragma once
// Motion vectors (previous minus current pixel position) from the G-buffer's depth and id, the
// current and previous cameras, and the previous world transforms of instances that moved; and the
// virtual motion of reflections, for SVGF's specular lobe (motion.frag.glsl).
// Input: G-buffer (normal + depth, id, specular radiance's reflection distance). Output: one RGBA32F
// target, xy: the surface's motion, zw: the reflected image's.
#include "renderer/gl/texture_buffer.h"
#include "renderer/gpu_scene/camera_setup.h"
#include "renderer/passes/fullscreen_stage.h"

#include <glm/glm.hpp>

#include <optional>
#include <vector>

namespace glint::renderer {

struct MovedInstance {
    float objectId = 0.0f;               // as the G-buffer's id target holds it
    glm::mat4 previousFromCurrent{1.0f}; // world space: where a point of the instance was last frame
};

class MotionPass {
public:
    MotionPass(gl::ProgramCache& programs, int width, int height);
    const gl::RenderTarget& execute(const gl::RenderTarget& gbuffer, const CameraSetup& camera,
                                    const CameraSetup& previousCamera, const std::vector<MovedInstance>& moved);
    const gl::RenderTarget& output() const { return motion_; }

private:
    gl::ProgramCache& programs_;
    gl::FullscreenTriangle triangle_;
    gl::RenderTarget motion_;
    std::optional<gl::TextureBuffer> moved_; // the moved instances, this frame's first (motion.frag.glsl)
};

} // namespace glint::renderer
