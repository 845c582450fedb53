#include "renderer/gl/shader_program.h"

#include "renderer/gl/include_resolver.h"
#include "shaders/embedded_shaders.h"

#include <chrono>
#include <stdexcept>

namespace glint::gl {
namespace {

std::string infoLog(GLuint object, bool isProgram) {
    GLint length = 0;
    isProgram ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length) : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    isProgram ? glGetProgramInfoLog(object, length, nullptr, log.data())
              : glGetShaderInfoLog(object, length, nullptr, log.data());
    log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
    return log;
}

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) { return std::chrono::duration<double, std::milli>(Clock::now() - start).count(); }

Shader compile(GLenum stage, const std::string& file, const Defines& defines, const ShaderSourceOptions& options,
               std::size_t& bytes, double& ms) {
    const ResolvedShader resolved = resolveIncludes(file, "#version 410 core", shaderPrelude(defines) + options.prelude,
                                                    options.lookup ? options.lookup : ShaderLookup(shaders::find));
    bytes = resolved.text.size();
    Shader shader(glCreateShader(stage));
    const char* text = resolved.text.c_str();
    glShaderSource(shader.get(), 1, &text, nullptr);
    const auto start = Clock::now();
    glCompileShader(shader.get());
    GLint ok = GL_FALSE;
    glGetShaderiv(shader.get(), GL_COMPILE_STATUS, &ok);
    ms = msSince(start);
    if (ok != GL_TRUE)
        throw std::runtime_error(file + ": GLSL compile failed:\n" + mapLogToFiles(infoLog(shader.get(), false), resolved.files));
    return shader;
}

} // namespace

std::string shaderPrelude(const Defines& defines) {
    std::string prelude;
    for (const auto& [name, value] : defines) prelude += "#define " + name + (value.empty() ? "" : " " + value) + "\n";
    prelude += "#define OUT(T) out T\n#define INOUT(T) inout T\n";
    return prelude;
}

ShaderProgram::ShaderProgram(const ProgramSource& source, const ShaderSourceOptions& options)
    : program_(glCreateProgram()), source_(source) {
    const Shader vertex = compile(GL_VERTEX_SHADER, source.vertexFile, source.defines, options, times_.vertexBytes,
                                  times_.vertexCompileMs);
    const Shader fragment = compile(GL_FRAGMENT_SHADER, source.fragmentFile, source.defines, options,
                                    times_.fragmentBytes, times_.fragmentCompileMs);
    glAttachShader(program_.get(), vertex.get());
    glAttachShader(program_.get(), fragment.get());
    for (std::size_t i = 0; i < source.fragmentOutputs.size(); ++i)
        glBindFragDataLocation(program_.get(), static_cast<GLuint>(i), source.fragmentOutputs[i].c_str());
    const auto start = Clock::now();
    glLinkProgram(program_.get());
    GLint ok = GL_FALSE;
    glGetProgramiv(program_.get(), GL_LINK_STATUS, &ok);
    times_.linkMs = msSince(start);
    glDetachShader(program_.get(), vertex.get());
    glDetachShader(program_.get(), fragment.get());
    if (ok != GL_TRUE)
        throw std::runtime_error(source.fragmentFile + ": GLSL link failed:\n" + infoLog(program_.get(), true));
}

} // namespace glint::gl
