#pragma once
// Patterns of the OpenGL 4.1 lint (plain string literals: moc trips on raw strings).
#include <regex>

namespace glint::test {

// Entry points newer than OpenGL 4.1 (macOS's ceiling), and direct state access.
inline const std::regex& forbiddenGlCall() {
    static const std::regex pattern(
        "\\b(glTexStorage\\w*|glBindImageTexture|glDispatchCompute\\w*|glMemoryBarrier\\w*|glClearTexImage|"
        "glCopyImageSubData|glCreate(Textures|Buffers|Framebuffers|VertexArrays|Renderbuffers|Samplers|"
        "ProgramPipelines|Queries|TransformFeedbacks)|glTexture\\w+|glNamed\\w+|glBufferStorage)\\s*\\(");
    return pattern;
}

// #version directives at the start of a line, and the string the loader puts in front of every stage.
inline const std::regex& versionDirective() {
    static const std::regex pattern("(?:^|\\n)[ \\t]*#[ \\t]*version\\b[^\\n]*|\"#version[^\"]*\"");
    return pattern;
}

} // namespace glint::test
