#include "mikktspace.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace glint::mikktspace {

namespace {

constexpr int kNoGroup = -1;

// Triangles around one welded vertex that share its tangent frame, summed as they join.
struct Group {
    std::uint32_t vertex = 0;
    bool orientationPreserving = false;
    glm::vec3 normal{0.0f};          // the vertex's unit normal
    glm::vec3 weightedTangents{0.0f}; // sum of projected triangle tangents times corner angle
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

// The corner angle, measured in the vertex's tangent plane.
float cornerAngle(const Input& in, std::size_t f, int i, const glm::vec3& normal) {
    const glm::vec3& here = in.positions[in.indices[3 * f + std::size_t(i)]];
    const glm::vec3& previous = in.positions[in.indices[3 * f + std::size_t((i + 2) % 3)]];
    const glm::vec3& next = in.positions[in.indices[3 * f + std::size_t((i + 1) % 3)]];
    const float cosine = glm::dot(projectedUnit(previous - here, normal), projectedUnit(next - here, normal));
    return std::acos(std::clamp(cosine, -1.0f, 1.0f));
}

// The original's recursive walk, as a loop: from triangle to edge neighbour around the group's
// vertex, taking triangles of the group's handedness. A uv-degenerate triangle adopts the
// handedness of the first group that reaches it.
void growGroup(const Input& in, Group& group, int groupIndex, std::size_t start, const std::vector<std::uint32_t>& welded,
               std::vector<TriangleFrame>& frames, CornerGroups& assigned, std::vector<std::size_t>& pending) {
    pending.assign(1, start);
    while (!pending.empty()) {
        const std::size_t f = pending.back();
        pending.pop_back();
        const int i = cornerOf(welded, f, group.vertex);
        if (i < 0 || assigned[f][std::size_t(i)] != kNoGroup) continue;
        TriangleFrame& frame = frames[f];
        const bool untouched = std::all_of(assigned[f].begin(), assigned[f].end(), [](int g) { return g == kNoGroup; });
        if (frame.uvDegenerate && untouched) frame.orientationPreserving = group.orientationPreserving;
        if (frame.orientationPreserving != group.orientationPreserving) continue;
        assigned[f][std::size_t(i)] = groupIndex;
        if (!frame.uvDegenerate)
            group.weightedTangents += cornerAngle(in, f, i, group.normal) * projectedUnit(frame.tangent, group.normal);
        for (int neighbour : {frame.neighbours[std::size_t((i + 2) % 3)], frame.neighbours[std::size_t(i)]})
            if (neighbour >= 0) pending.push_back(std::size_t(neighbour));
    }
}

std::vector<Group> buildGroups(const Input& in, const std::vector<std::uint32_t>& welded,
                               std::vector<TriangleFrame>& frames, CornerGroups& assigned) {
    std::vector<Group> groups;
    std::vector<std::size_t> pending;
    for (std::size_t f = 0; f < frames.size(); ++f) {
        if (frames[f].uvDegenerate || frames[f].positionDegenerate) continue;
        for (std::size_t i = 0; i < 3; ++i) {
            if (assigned[f][i] != kNoGroup) continue;
            const std::uint32_t vertex = welded[3 * f + i];
            groups.push_back({vertex, frames[f].orientationPreserving, unitOrZero(in.normals[vertex]), glm::vec3(0.0f)});
            growGroup(in, groups.back(), int(groups.size() - 1), f, welded, frames, assigned, pending);
        }
    }
    return groups;
}

std::optional<glm::vec4> groupTangent(const Group& group) {
    const glm::vec3 tangent = projectedUnit(group.weightedTangents, group.normal);
    if (!(glm::length(tangent) > 0.5f)) return std::nullopt;
    return glm::vec4(tangent, group.orientationPreserving ? 1.0f : -1.0f);
}

} // namespace

std::vector<glm::vec4> cornerTangents(const Input& in, const std::vector<std::uint32_t>& welded,
                                      std::vector<TriangleFrame>& frames) {
    CornerGroups assigned(frames.size(), {kNoGroup, kNoGroup, kNoGroup});
    const std::vector<Group> groups = buildGroups(in, welded, frames, assigned);
    std::vector<std::optional<glm::vec4>> perGroup;
    perGroup.reserve(groups.size());
    for (const Group& group : groups) perGroup.push_back(groupTangent(group));

    std::vector<std::optional<glm::vec4>> perCorner(welded.size());
    std::vector<std::optional<glm::vec4>> anyForVertex(in.positions.size());
    for (std::size_t c = 0; c < welded.size(); ++c) {
        const int g = assigned[c / 3][c % 3];
        if (g != kNoGroup) perCorner[c] = perGroup[std::size_t(g)];
        if (perCorner[c] && !anyForVertex[welded[c]]) anyForVertex[welded[c]] = perCorner[c];
    }
    // Corners of degenerate triangles take the frame another triangle gave their vertex.
    std::vector<glm::vec4> result(welded.size());
    for (std::size_t c = 0; c < welded.size(); ++c) {
        const std::optional<glm::vec4>& own = perCorner[c] ? perCorner[c] : anyForVertex[welded[c]];
        result[c] = own ? *own : fallbackTangent(in.normals[welded[c]]);
    }
    return result;
}

glm::vec4 fallbackTangent(const glm::vec3& normal) {
    const glm::vec3 axis = std::abs(normal.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    const glm::vec3 tangent = projectedUnit(axis, unitOrZero(normal));
    return glm::vec4(tangent, 1.0f);
}

} // namespace glint::mikktspace
