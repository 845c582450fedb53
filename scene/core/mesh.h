#pragma once
#include "ids.h"
#include "shared_array.h"

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace glint {

// One glTF primitive, always as an indexed triangle list in float attributes
// (normalized integer and sparse accessors are expanded on load).
// Attribute arrays are either empty or as long as positions. They are shared between copies until
// written (shared_array.h), so copying a mesh copies no vertex data.
struct Primitive {
    SharedArray<glm::vec3> positions;
    SharedArray<glm::vec3> normals;
    SharedArray<glm::vec4> tangents; // xyz + handedness w (MikkTSpace)
    SharedArray<glm::vec2> uv0;
    SharedArray<glm::vec2> uv1;
    SharedArray<glm::vec4> colors;   // COLOR_0 as RGBA
    SharedArray<std::uint32_t> indices;
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
