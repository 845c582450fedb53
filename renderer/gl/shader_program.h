#pragma once
// Compiles and links a vertex + fragment program from embedded GLSL files. Every stage starts
// `#version 410 core` and a prelude of the caller's defines plus the macros shared chunks use
// (OUT(T), INOUT(T)). Compile and link errors are thrown with file:line locations.
#include "renderer/gl/gl_objects.h"

#include <map>
#include <string>
#include <vector>

namespace glint::gl {

using Defines = std::map<std::string, std::string>; // NAME -> value ("" for a bare #define)

struct ProgramSource {
    std::string vertexFile;   // e.g. "fullscreen.vert.glsl"
    std::string fragmentFile; // e.g. "pathtrace/main.frag.glsl"
    Defines defines;
    std::vector<std::string> fragmentOutputs; // bound to colour attachments 0, 1, ... in order
};

class ShaderProgram {
public:
    explicit ShaderProgram(const ProgramSource& source); // throws std::runtime_error
    GLuint id() const { return program_.get(); }
    void use() const { glUseProgram(program_.get()); }
    GLint uniform(const char* name) const { return glGetUniformLocation(program_.get(), name); }

private:
    Program program_;
};

// The text both stages get after #version: the defines and the shared macros.
std::string shaderPrelude(const Defines& defines);

} // namespace glint::gl
