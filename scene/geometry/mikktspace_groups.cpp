#include "mikktspace.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace glint::mikktspace {

namespace {

constexpr int kNoGroup = -1;

// Triangles around one welded vertex that share its tangent frame.
struct Group {
    std::uint32_t vertex = 0;
    bool orientationPreserving = false;
    std::vector<std::size_t> triangles;
};

using CornerGroups = std::vector<std::array<int, 3>>;

int cornerOf(const std::vector<std::uint32_t>& welded, std::size_t f, std::uint32_t vertex) {
    for (int i = 0; i < 3; ++i)
        if (welded[3 * f + std::size_t(i)] == vertex) return i;
    return -1;
}

glm::vec3 projectedUnit(const glm::vec3& v, const glm::vec3& normal) {
    const glm::vec3 inPlane = v - glm::dot(normal, v) * normal;
    const float length = glm::length(inPlane);
    return length > 0.0f ? inPlane / length : inPlane;
}

glm::vec3 unitOrZero(const glm::vec3& v) {
    const float length = glm::length(v);
    return length > 0.0f ? v / length : glm::vec3(0.0f);
}

// The original's recursive walk, as a loop: from triangle to edge neighbour around the group's
// vertex, taking triangles of the group's handedness. A uv-degenerate triangle adopts the
// handedness of the first group that reaches it.
void growGroup(Group& group, int groupIndex, std::size_t start, const std::vector<std::uint32_t>& welded,
               std::vector<TriangleFrame>& frames, CornerGroups& assigned) {
    std::vector<std::size_t> pending{start};
    while (!pending.empty()) {
        const std::size_t f = pending.back();
        pending.pop_back();
        const int i = cornerOf(welded, f, group.vertex);
        if (i < 0 || assigned[f][std::size_t(i)] != kNoGroup) continue;
        TriangleFrame& frame = frames[f];
        const bool untouched = std::all_of(assigned[f].begin(), assigned[f].end(), [](int g) { return g == kNoGroup; });
        if (frame.uvDegenerate && untouched) frame.orientationPreserving = group.orientationPreserving;
        if (frame.orientationPreserving != group.orientationPreserving) continue;
        group.triangles.push_back(f);
        assigned[f][std::size_t(i)] = groupIndex;
        for (int neighbour : {frame.neighbours[std::size_t((i + 2) % 3)], frame.neighbours[std::size_t(i)]})
            if (neighbour >= 0) pending.push_back(std::size_t(neighbour));
    }
}

std::vector<Group> buildGroups(const std::vector<std::uint32_t>& welded, std::vector<TriangleFrame>& frames,
                               CornerGroups& assigned) {
    std::vector<Group> groups;
    for (std::size_t f = 0; f < frames.size(); ++f) {
        if (frames[f].uvDegenerate || frames[f].positionDegenerate) continue;
        for (std::size_t i = 0; i < 3; ++i) {
            if (assigned[f][i] != kNoGroup) continue;
            groups.push_back({welded[3 * f + i], frames[f].orientationPreserving, {}});
            growGroup(groups.back(), int(groups.size() - 1), f, welded, frames, assigned);
        }
    }
    return groups;
}

// The corner angle, measured in the vertex's tangent plane.
float cornerAngle(const Input& in, std::size_t f, int i, const glm::vec3& normal) {
    const glm::vec3& here = in.positions[in.indices[3 * f + std::size_t(i)]];
    const glm::vec3& previous = in.positions[in.indices[3 * f + std::size_t((i + 2) % 3)]];
    const glm::vec3& next = in.positions[in.indices[3 * f + std::size_t((i + 1) % 3)]];
    const float cosine = glm::dot(projectedUnit(previous - here, normal), projectedUnit(next - here, normal));
    return std::acos(std::clamp(cosine, -1.0f, 1.0f));
}

std::optional<glm::vec4> groupTangent(const Input& in, const Group& group, const std::vector<std::uint32_t>& welded,
                                      const std::vector<TriangleFrame>& frames) {
    const glm::vec3 normal = unitOrZero(in.normals[group.vertex]);
    glm::vec3 sum(0.0f);
    for (std::size_t f : group.triangles) {
        if (frames[f].uvDegenerate) continue;
        sum += cornerAngle(in, f, cornerOf(welded, f, group.vertex), normal) * projectedUnit(frames[f].tangent, normal);
    }
    const glm::vec3 tangent = projectedUnit(sum, normal);
    if (!(glm::length(tangent) > 0.5f)) return std::nullopt;
    return glm::vec4(tangent, group.orientationPreserving ? 1.0f : -1.0f);
}

} // namespace

std::vector<glm::vec4> cornerTangents(const Input& in, const std::vector<std::uint32_t>& welded,
                                      std::vector<TriangleFrame>& frames) {
    CornerGroups assigned(frames.size(), {kNoGroup, kNoGroup, kNoGroup});
    const std::vector<Group> groups = buildGroups(welded, frames, assigned);
    std::vector<std::optional<glm::vec4>> perGroup;
    for (const Group& group : groups) perGroup.push_back(groupTangent(in, group, welded, frames));

    std::vector<std::optional<glm::vec4>> perCorner(welded.size());
    std::vector<std::optional<glm::vec4>> anyForVertex(in.positions.size());
    for (std::size_t c = 0; c < welded.size(); ++c) {
        const int g = assigned[c / 3][c % 3];
        if (g != kNoGroup) perCorner[c] = perGroup[std::size_t(g)];
        if (perCorner[c] && !anyForVertex[welded[c]]) anyForVertex[welded[c]] = perCorner[c];
    }
    // Corners of degenerate triangles take the frame another triangle gave their vertex.
    std::vector<glm::vec4> result(welded.size());
    for (std::size_t c = 0; c < welded.size(); ++c)
        result[c] = perCorner[c].value_or(anyForVertex[welded[c]].value_or(fallbackTangent(in.normals[welded[c]])));
    return result;
}

glm::vec4 fallbackTangent(const glm::vec3& normal) {
    const glm::vec3 axis = std::abs(normal.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    const glm::vec3 tangent = projectedUnit(axis, unitOrZero(normal));
    return glm::vec4(tangent, 1.0f);
}

} // namespace glint::mikktspace
