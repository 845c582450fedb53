#pragma once
// Raster preview of the scene for the editor's viewport: solid (headlight-shaded) and wireframe
// views of meshes and analytic shapes (tessellated), drawn into any framebuffer of the current
// context. No GL header here, so Qt code can hold one; the context that created it must be current.
#include "scene/core/scene.h"

#include <glm/glm.hpp>

#include <memory>

namespace glint::renderer::raster {

enum class PreviewStyle { Solid, Wireframe };

struct PreviewView {
    glm::mat4 clipFromWorld{1.0f};
    glm::vec3 eye{0.0f};
    int width = 1;
    int height = 1;
    PreviewStyle style = PreviewStyle::Solid;
    NodeId highlight{}; // drawn in the selection colour
};

class PreviewPass {
public:
    PreviewPass();
    ~PreviewPass();
    PreviewPass(const PreviewPass&) = delete;
    PreviewPass& operator=(const PreviewPass&) = delete;

    // Vertex buffers are cached per mesh and per shape; call after geometry changes.
    void invalidate();
    // Clears and draws; transforms and visibility are read from `scene` on every call.
    void draw(const Scene& scene, unsigned int framebuffer, const PreviewView& view);

private:
    struct State;
    std::unique_ptr<State> state_;
};

} // namespace glint::renderer::raster
