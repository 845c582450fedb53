#pragma once
#include "ids.h"

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace glint {

// One glTF primitive, always as an indexed triangle list in float attributes
// (normalized integer and sparse accessors are expanded on load).
// Attribute arrays are either empty or as long as positions.
struct Primitive {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec4> tangents; // xyz + handedness w (MikkTSpace)
    std::vector<glm::vec2> uv0;
    std::vector<glm::vec2> uv1;
    std::vector<glm::vec4> colors;   // COLOR_0 as RGBA
    std::vector<std::uint32_t> indices;
    MaterialId material{};           // none: the glTF default material
    nlohmann::json unknown;

    std::size_t triangleCount() const { return indices.size() / 3; }
    friend bool operator==(const Primitive&, const Primitive&) = default;
};

struct Mesh {
    std::string name;
    std::vector<Primitive> primitives;
    nlohmann::json unknown;

    std::size_t triangleCount() const;
    friend bool operator==(const Mesh&, const Mesh&) = default;
};

} // namespace glint
