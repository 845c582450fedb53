#include "renderer/gl/program_cache.h"

namespace glint::gl {
namespace {

std::string keyOf(const ProgramSource& source) {
    std::string key = source.vertexFile + "|" + source.fragmentFile + "|" + shaderPrelude(source.defines);
    for (const auto& output : source.fragmentOutputs) key += "|" + output;
    return key;
}

} // namespace

const ShaderProgram& ProgramCache::get(const ProgramSource& source) {
    auto& slot = programs_[keyOf(source)];
    if (!slot) {
        slot = std::make_unique<ShaderProgram>(source, options_);
        built_.push_back(slot.get());
    }
    return *slot;
}

} // namespace glint::gl
