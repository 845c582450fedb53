#include "geometry.h"

#include "mikktspace.h"

#include <algorithm>
#include <cmath>

namespace glint {

namespace {

bool allFinite(const auto& values) {
    return std::all_of(values.begin(), values.end(), [](const auto& v) {
        for (int i = 0; i < v.length(); ++i)
            if (!std::isfinite(v[i])) return false;
        return true;
    });
}

bool canGenerate(const Primitive& p) {
    const std::size_t n = p.positions.size();
    return !p.indices.empty() && p.indices.size() % 3 == 0 && p.normals.size() == n && p.uv0.size() == n
        && std::all_of(p.indices.begin(), p.indices.end(), [n](std::uint32_t i) { return i < n; })
        && allFinite(p.positions) && allFinite(p.normals) && allFinite(p.uv0);
}

template <class T>
void duplicateVertex(std::vector<T>& attribute, std::uint32_t vertex) {
    if (!attribute.empty()) attribute.push_back(attribute[vertex]);
}

// MikkTSpace gives a tangent per corner; a vertex whose corners disagree (a uv mirror seam) is
// split so each copy carries one tangent, as glTF stores tangents per vertex.
void storePerVertex(Primitive& p, const std::vector<glm::vec4>& cornerTangents) {
    const std::size_t originalCount = p.positions.size();
    std::vector<bool> taken(originalCount, false);
    std::vector<std::vector<std::uint32_t>> copies(originalCount); // extra vertices made for a vertex
    p.tangents.resize(originalCount);
    for (std::size_t v = 0; v < originalCount; ++v) p.tangents[v] = mikktspace::fallbackTangent(p.normals[v]); // unused ones
    for (std::size_t c = 0; c < p.indices.size(); ++c) {
        const std::uint32_t v = p.indices[c];
        const glm::vec4& t = cornerTangents[c];
        if (!taken[v] || p.tangents[v] == t) {
            taken[v] = true;
            p.tangents[v] = t;
            continue;
        }
        const auto same = std::find_if(copies[v].begin(), copies[v].end(),
                                       [&](std::uint32_t copy) { return p.tangents[copy] == t; });
        if (same != copies[v].end()) {
            p.indices[c] = *same;
            continue;
        }
        const auto copy = std::uint32_t(p.positions.size());
        duplicateVertex(p.positions.edit(), v);
        duplicateVertex(p.normals.edit(), v);
        duplicateVertex(p.uv0.edit(), v);
        duplicateVertex(p.uv1.edit(), v);
        duplicateVertex(p.colors.edit(), v);
        p.tangents.push_back(t);
        copies[v].push_back(copy);
        p.indices[c] = copy;
    }
}

} // namespace

bool generateTangents(Primitive& p) {
    if (!canGenerate(p)) {
        p.tangents.clear();
        return false;
    }
    std::vector<glm::vec4> corners = mikktspace::generate({p.positions, p.normals, p.uv0, p.indices});
    // glTF's uv origin is the image's top-left, so v runs opposite to the uv space MikkTSpace
    // assumes; glTF's bitangent = cross(normal, tangent) * w must point along -dP/dv, which is the
    // MikkTSpace sign negated (as three.js's negateSign and Blender's exporter do).
    for (glm::vec4& t : corners) t.w = -t.w;
    storePerVertex(p, corners);
    return true;
}

} // namespace glint
