#pragma once
// One triangle that covers the viewport; the vertex shader (fullscreen.vert.glsl) makes its corners
// from gl_VertexID, so the only state is the empty vertex array core profiles require.
#include "renderer/gl/gl_objects.h"

namespace glint::gl {

class FullscreenTriangle {
public:
    FullscreenTriangle() : vao_(makeVertexArray()) {}
    void draw() const {
        glBindVertexArray(vao_.get());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glBindVertexArray(0);
    }

private:
    VertexArray vao_;
};

} // namespace glint::gl
