#pragma once
// A re-implementation of Morten Mikkelsen's MikkTSpace (mikktspace.c, the tangent convention glTF
// requires), for indexed triangle lists. The stages follow the original:
//  1. weld corners whose position, normal and uv are all equal (the original's vertex identity);
//  2. per triangle, the tangent and bitangent from the uv derivatives, the handedness (sign of the
//     uv area), and whether the uv mapping is degenerate ("group with any");
//  3. neighbours across shared edges; triangles with coincident corners are left out;
//  4. per welded vertex, groups of edge-connected triangles of equal handedness;
//  5. per group, the tangents projected into the vertex's tangent plane, weighted by the corner
//     angle, summed and normalised; w = +1 or -1 by handedness.
// Deviations, all for cases the original leaves to a default: a corner in no group (all its uvs
// degenerate) gets a tangent orthogonal to its normal and w = +1; the original's sub-groups are
// not formed (with its default 180-degree threshold they only split exactly opposite tangents).
#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace glint::mikktspace {

struct Input {
    const std::vector<glm::vec3>& positions;
    const std::vector<glm::vec3>& normals;
    const std::vector<glm::vec2>& uvs;
    const std::vector<std::uint32_t>& indices; // triangle list; every index < positions.size()
};

struct TriangleFrame {
    glm::vec3 tangent{0.0f};   // unit dP/du (sign-corrected for mirrored uvs), or zero
    bool orientationPreserving = false;
    bool uvDegenerate = false; // joins any group ("GROUP_WITH_ANY")
    bool positionDegenerate = false;
    std::array<int, 3> neighbours{-1, -1, -1}; // across edge (corner i, corner i+1)
};

// Stage 1: per corner, the welded vertex id (the smallest index with identical attributes).
std::vector<std::uint32_t> weldCorners(const Input& input);
// Stages 2 and 3.
std::vector<TriangleFrame> triangleFrames(const Input& input, const std::vector<std::uint32_t>& welded);
void findNeighbours(const std::vector<std::uint32_t>& welded, std::vector<TriangleFrame>& frames);
// Stages 4 and 5: a tangent per corner (xyz unit, w = +-1).
std::vector<glm::vec4> cornerTangents(const Input& input, const std::vector<std::uint32_t>& welded,
                                      std::vector<TriangleFrame>& frames);

// Any unit vector orthogonal to the normal, w = +1: for corners whose uvs define no direction.
glm::vec4 fallbackTangent(const glm::vec3& normal);

// All stages.
std::vector<glm::vec4> generate(const Input& input);

} // namespace glint::mikktspace
