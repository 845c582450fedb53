#pragma once
// Move-only owners of GL object names. The context that created a name must be current when
// its owner is destroyed.
#include <epoxy/gl.h>

#include <utility>

namespace glint::gl {

template <void (*Delete)(GLuint)>
class GlName {
public:
    GlName() = default;
    explicit GlName(GLuint name) : name_(name) {}
    ~GlName() { reset(); }
    GlName(GlName&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
    GlName& operator=(GlName&& other) noexcept {
        if (this != &other) {
            reset();
            name_ = std::exchange(other.name_, 0);
        }
        return *this;
    }
    GlName(const GlName&) = delete;
    GlName& operator=(const GlName&) = delete;

    GLuint get() const { return name_; }
    explicit operator bool() const { return name_ != 0; }
    void reset() {
        if (name_) Delete(name_);
        name_ = 0;
    }

private:
    GLuint name_ = 0;
};

namespace detail {
inline void deleteTexture(GLuint n) { glDeleteTextures(1, &n); }
inline void deleteBuffer(GLuint n) { glDeleteBuffers(1, &n); }
inline void deleteFramebuffer(GLuint n) { glDeleteFramebuffers(1, &n); }
inline void deleteVertexArray(GLuint n) { glDeleteVertexArrays(1, &n); }
inline void deleteProgram(GLuint n) { glDeleteProgram(n); }
inline void deleteShader(GLuint n) { glDeleteShader(n); }
inline void deleteQuery(GLuint n) { glDeleteQueries(1, &n); }
} // namespace detail

using Texture = GlName<detail::deleteTexture>;
using Buffer = GlName<detail::deleteBuffer>;
using Framebuffer = GlName<detail::deleteFramebuffer>;
using VertexArray = GlName<detail::deleteVertexArray>;
using Program = GlName<detail::deleteProgram>;
using Shader = GlName<detail::deleteShader>;
using Query = GlName<detail::deleteQuery>;

inline Texture makeTexture() { GLuint n = 0; glGenTextures(1, &n); return Texture(n); }
inline Buffer makeBuffer() { GLuint n = 0; glGenBuffers(1, &n); return Buffer(n); }
inline Framebuffer makeFramebuffer() { GLuint n = 0; glGenFramebuffers(1, &n); return Framebuffer(n); }
inline Query makeQuery() { GLuint n = 0; glGenQueries(1, &n); return Query(n); }
inline VertexArray makeVertexArray() { GLuint n = 0; glGenVertexArrays(1, &n); return VertexArray(n); }

} // namespace glint::gl
