#pragma once
// Compiled programs keyed by their sources and defines: each shader variant is compiled once per
// context (JIT + first draw costs 170-350 ms a program on llvmpipe).
#include "renderer/gl/shader_program.h"

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace glint::gl {

class ProgramCache {
public:
    const ShaderProgram& get(const ProgramSource& source);
    std::size_t size() const { return programs_.size(); }
    // The programs in the order they were built (their sources and build times).
    const std::vector<const ShaderProgram*>& built() const { return built_; }
    // Source options for programs built from now on (`glint bench --suite shaders`); renders keep
    // the defaults.
    void setSourceOptions(ShaderSourceOptions options) { options_ = std::move(options); }

private:
    std::map<std::string, std::unique_ptr<ShaderProgram>> programs_;
    std::vector<const ShaderProgram*> built_;
    ShaderSourceOptions options_;
};

} // namespace glint::gl
