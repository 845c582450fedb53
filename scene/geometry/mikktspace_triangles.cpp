#include "mikktspace.h"

#include <algorithm>
#include <numeric>
#include <optional>
#include <tuple>

namespace glint::mikktspace {

namespace {

auto attributeKey(const Input& in, std::uint32_t v) {
    const glm::vec3& p = in.positions[v];
    const glm::vec3& n = in.normals[v];
    const glm::vec2& t = in.uvs[v];
    return std::make_tuple(p.x, p.y, p.z, n.x, n.y, n.z, t.x, t.y);
}

// The original's thresholds: tiny uv areas and tangent magnitudes count as degenerate.
bool notZero(float x) { return std::abs(x) > 1.17549435e-38f; }

// An edge keyed by its unordered vertex pair, so both walks of one edge sort next to each other.
struct Edge {
    std::uint64_t key;  // min vertex << 32 | max vertex
    std::uint32_t corner; // 3 * triangle + i: the edge from corner i to corner i + 1
    bool forward;         // walked from the smaller vertex to the larger
    auto order() const { return std::make_pair(key, corner); }
};

Edge makeEdge(std::uint32_t from, std::uint32_t to, std::size_t corner) {
    const std::uint64_t low = std::min(from, to), high = std::max(from, to);
    return {low << 32 | high, std::uint32_t(corner), from < to};
}

} // namespace

std::vector<std::uint32_t> weldCorners(const Input& in) {
    std::vector<std::uint32_t> order(in.positions.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return attributeKey(in, a) < attributeKey(in, b); });
    std::vector<std::uint32_t> representative(in.positions.size());
    for (std::size_t i = 0; i < order.size(); ++i) {
        const bool sameAsPrevious = i > 0 && attributeKey(in, order[i]) == attributeKey(in, order[i - 1]);
        representative[order[i]] = sameAsPrevious ? representative[order[i - 1]] : order[i];
    }
    std::vector<std::uint32_t> welded(in.indices.size());
    for (std::size_t c = 0; c < in.indices.size(); ++c) welded[c] = representative[in.indices[c]];
    return welded;
}

std::vector<TriangleFrame> triangleFrames(const Input& in, const std::vector<std::uint32_t>& welded) {
    std::vector<TriangleFrame> frames(in.indices.size() / 3);
    for (std::size_t f = 0; f < frames.size(); ++f) {
        const std::uint32_t* corner = &in.indices[3 * f];
        const glm::vec3 &p0 = in.positions[corner[0]], &p1 = in.positions[corner[1]], &p2 = in.positions[corner[2]];
        const glm::vec2 t21 = in.uvs[corner[1]] - in.uvs[corner[0]];
        const glm::vec2 t31 = in.uvs[corner[2]] - in.uvs[corner[0]];
        const float signedArea = t21.x * t31.y - t21.y * t31.x;
        const glm::vec3 dPdu = t31.y * (p1 - p0) - t21.y * (p2 - p0);
        const glm::vec3 dPdv = t21.x * (p2 - p0) - t31.x * (p1 - p0);
        TriangleFrame& frame = frames[f];
        frame.orientationPreserving = signedArea > 0.0f;
        frame.positionDegenerate = p0 == p1 || p0 == p2 || p1 == p2 || welded[3 * f] == welded[3 * f + 1]
                                || welded[3 * f] == welded[3 * f + 2] || welded[3 * f + 1] == welded[3 * f + 2];
        const float length = glm::length(dPdu);
        const bool usable = notZero(signedArea) && notZero(length / std::abs(signedArea))
                         && notZero(glm::length(dPdv) / std::abs(signedArea));
        frame.uvDegenerate = !usable;
        if (usable) frame.tangent = dPdu * ((frame.orientationPreserving ? 1.0f : -1.0f) / length);
    }
    return frames;
}

// Triangles meet across an edge that one walks a->b and the other b->a (consistent winding). Each
// edge is paired with the first (lowest corner) opposite walk of it, as the original does.
void findNeighbours(const std::vector<std::uint32_t>& welded, std::vector<TriangleFrame>& frames) {
    std::vector<Edge> edges;
    edges.reserve(welded.size());
    for (std::size_t f = 0; f < frames.size(); ++f) {
        if (frames[f].positionDegenerate) continue;
        for (std::size_t i = 0; i < 3; ++i)
            edges.push_back(makeEdge(welded[3 * f + i], welded[3 * f + (i + 1) % 3], 3 * f + i));
    }
    std::sort(edges.begin(), edges.end(), [](const Edge& a, const Edge& b) { return a.order() < b.order(); });
    for (std::size_t runStart = 0, runEnd = 0; runStart < edges.size(); runStart = runEnd) {
        while (runEnd < edges.size() && edges[runEnd].key == edges[runStart].key) ++runEnd;
        std::array<std::optional<std::uint32_t>, 2> firstWalk; // lowest corner per direction
        for (std::size_t e = runEnd; e-- > runStart;) firstWalk[edges[e].forward] = edges[e].corner;
        for (std::size_t e = runStart; e < runEnd; ++e)
            if (const auto other = firstWalk[!edges[e].forward])
                frames[edges[e].corner / 3].neighbours[edges[e].corner % 3] = int(*other / 3);
    }
}

std::vector<glm::vec4> generate(const Input& input) {
    const std::vector<std::uint32_t> welded = weldCorners(input);
    std::vector<TriangleFrame> frames = triangleFrames(input, welded);
    findNeighbours(welded, frames);
    return cornerTangents(input, welded, frames);
}

} // namespace glint::mikktspace
