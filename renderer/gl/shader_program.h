#pragma once
// Compiles and links a vertex + fragment program from embedded GLSL files. Every stage starts
// `#version 410 core` and a prelude of the caller's defines plus the macros shared chunks use
// (OUT(T), INOUT(T)). Compile and link errors are thrown with file:line locations.
#include "renderer/gl/gl_objects.h"
#include "renderer/gl/include_resolver.h"

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

// Where the GLSL comes from, for shader work and compile-time experiments (`glint bench --suite
// shaders`): `lookup` reads files instead of the embedded copies (empty: embedded), and `prelude`
// is added after the defines. Renders use the defaults.
struct ShaderSourceOptions {
    ShaderLookup lookup;
    std::string prelude;
};

// What building a program took: glCompileShader per stage and glLinkProgram, each up to its status
// query (which waits for the driver). Drivers may still defer work to the first draw.
struct ProgramBuildTimes {
    std::size_t vertexBytes = 0;   // source after includes, as the driver gets it
    std::size_t fragmentBytes = 0;
    double vertexCompileMs = 0.0;
    double fragmentCompileMs = 0.0;
    double linkMs = 0.0;
};

class ShaderProgram {
public:
    // Throws std::runtime_error.
    explicit ShaderProgram(const ProgramSource& source, const ShaderSourceOptions& options = {});
    GLuint id() const { return program_.get(); }
    const ProgramSource& source() const { return source_; }
    const ProgramBuildTimes& buildTimes() const { return times_; }
    void use() const { glUseProgram(program_.get()); }
    GLint uniform(const char* name) const { return glGetUniformLocation(program_.get(), name); }

private:
    Program program_;
    ProgramSource source_;
    ProgramBuildTimes times_;
};

// The text both stages get after #version: the defines and the shared macros.
std::string shaderPrelude(const Defines& defines);

} // namespace glint::gl
