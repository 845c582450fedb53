#include "geometry.h"

#include <cmath>

namespace glint {

namespace {

glm::vec3 faceNormal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::vec3 n = glm::cross(b - a, c - a);
    const float length = glm::length(n);
    return length > 0.0f && std::isfinite(length) ? n / length : glm::vec3(0.0f, 1.0f, 0.0f);
}

// Every attribute array that is present, gathered in the order of `corners`.
template <class T>
void gather(std::vector<T>& attribute, const std::vector<std::uint32_t>& corners) {
    if (attribute.empty()) return;
    std::vector<T> split;
    split.reserve(corners.size());
    for (std::uint32_t index : corners) split.push_back(attribute.at(index));
    attribute = std::move(split);
}

} // namespace

void generateFlatNormals(Primitive& p) {
    const std::vector<std::uint32_t> corners = p.indices;
    gather(p.positions.edit(), corners);
    gather(p.uv0.edit(), corners);
    gather(p.uv1.edit(), corners);
    gather(p.colors.edit(), corners);
    p.tangents.clear(); // glTF: tangents without normals are meaningless; regenerate if needed
    p.normals.assign(p.positions.size(), glm::vec3(0.0f));
    for (std::size_t i = 0; i + 2 < p.positions.size(); i += 3) {
        const glm::vec3 n = faceNormal(p.positions[i], p.positions[i + 1], p.positions[i + 2]);
        p.normals[i] = p.normals[i + 1] = p.normals[i + 2] = n;
    }
    p.indices.resize(corners.size());
    for (std::size_t i = 0; i < p.indices.size(); ++i) p.indices[i] = std::uint32_t(i);
}

} // namespace glint
