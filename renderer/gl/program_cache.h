#pragma once
// Compiled programs keyed by their sources and defines: each shader variant is compiled once per
// context (JIT + first draw costs 170-350 ms a program on llvmpipe).
#include "renderer/gl/shader_program.h"

#include <map>
#include <memory>
#include <string>

namespace glint::gl {

class ProgramCache {
public:
    const ShaderProgram& get(const ProgramSource& source);
    std::size_t size() const { return programs_.size(); }

private:
    std::map<std::string, std::unique_ptr<ShaderProgram>> programs_;
};

} // namespace glint::gl
