#pragma once
// The flattened two-level BVH as the path tracer reads it: five buffer textures. This file is the
// contract between the CPU side (renderer/bvh, flatten.cpp writes it) and the GLSL side
// (shaders/bvh/*.glsl reads it). Change both or neither.
//
// Texture buffers and the sampler uniforms that read them (set their units with glUniform1i):
//
//   uBvhNodes             usamplerBuffer  GL_RGBA32UI  1 texel per node
//   uBvhLevels            usamplerBuffer  GL_RGBA32UI  2 texels per level (each mesh BVH, the top level)
//   uBvhTrianglePositions samplerBuffer   GL_RGBA32F   3 texels per triangle slot
//   uBvhTriangleVertices  usamplerBuffer  GL_RGBA32UI  1 texel per triangle slot
//   uBvhInstances         usamplerBuffer  GL_RGBA32UI  4 texels per instance
//   uBvhTopLevel          int             the top level's level index; -1: no instances
//
// Nodes (both levels share the node buffer). Mesh BVHs come first, one after another in the order
// of FlatScene::meshes; the top level follows them, starting at node index meshNodeCount. Moving an
// object rewrites only the top-level tail of the node buffer, the top level's two level texels and
// the instance buffer (flattenTopLevel()); the mesh part keeps its bytes.
//
//   uBvhNodes[n] = (lo.x | hi.x << 16, lo.y | hi.y << 16, lo.z | hi.z << 16, link)
//       The node's box on its level's grid (renderer/bvh/box_grid.h): 16-bit grid coordinates,
//       lo rounded down and hi up, so the box a walk tests always holds the exact one. A box
//       corner in the level's space is origin + float(q) * scale (the level texels below); scale
//       is a power of two, so that sum is the only rounding and the CPU computes it to the bit.
//       link = (first << 4) | count, packed, so testing a child's box reads the child's link too
//       and a walk step fetches one texel per child:
//       count == 0: an interior node; its two children are the nodes `first` and `first + 1`
//                   (siblings are always adjacent, so one fetch range reads both children).
//       count > 0 : a leaf.
//                   mesh level: triangle slots first .. first + count - 1 (count <= kMaxLeafTriangles)
//                   top level : exactly one instance, count == 1, `first` is the instance index.
//   All indices are absolute (already offset for the mesh's place in the buffers). A node's children
//   always have larger indices than the node itself, so following links can never cycle.
//
// Levels: mesh i is level i (the order of FlatScene::meshes), the top level is level meshes.size().
//   uBvhLevels[2l + 0] = (origin.x, origin.y, origin.z, root link)  origin as float bits: the
//                        root's exact lower corner in the level's space (mesh: the mesh's local
//                        space; top: world); root link packed as above
//   uBvhLevels[2l + 1] = (scale.x, scale.y, scale.z, root)  scale as float bits, each a power of
//                        two with origin + 65535 * scale >= the root's upper corner; root: the
//                        root's absolute node index (a walk tests the top level's root box first)
//   An empty mesh has origin 0, scale 1, a root link of 0 and its would-be root index (no instance
//   may use it).
//
// Triangle slots: each mesh's triangles in BVH leaf order, meshes one after another.
//   uBvhTrianglePositions[3s + k] = (vertex k of slot s: x, y, z, w) in mesh-local space, k = 0, 1, 2;
//                                   w = 0, except the renderer's mark of the slot in texel 3s
//                                   (renderer/gpu_scene/mesh_data.h, markCulledTriangles)
//   uBvhTriangleVertices[s]       = (v0, v1, v2, material)
//       v0..v2: vertex indices into the scene's vertex attribute arrays: every mesh's vertices
//               concatenated in the order of FlatScene::meshes, and within a mesh its primitives'
//               vertices in primitive order (MeshTriangles::positions). A mesh's first vertex is at
//               FlatScene::meshes[i].firstVertex. Normals, tangents and UVs uploaded by the renderer
//               must use exactly this order.
//       material: the material index given to trianglesFromMesh() (the renderer's material table).
//   Winding: v0, v1, v2 as in the glTF primitive; the geometric normal is cross(p1 - p0, p2 - p0)
//   (counter-clockwise front faces), transformed to world space with the instance's normal matrix.
//
// Instances (4 texels each, all as uint; rows 0..2 are float bits: read them with uintBitsToFloat):
//   uBvhInstances[4i + r] = row r of localFromWorld (3x4 affine), r = 0, 1, 2:
//                           (m[0][r], m[1][r], m[2][r], m[3][r]) for a column-major glm::mat4 m,
//                           so localPoint.r = dot(row r, vec4(worldPoint, 1)).
//                           The world normal of a local normal n is n.x*row0.xyz + n.y*row1.xyz +
//                           n.z*row2.xyz (the transpose of localFromWorld), then normalised.
//   uBvhInstances[4i + 3] = (kind, target, objectId, flags)
//       kind   : kInstanceMesh (0) or kInstanceShape (1)
//       target : mesh: the mesh's index in FlatScene::meshes, which is its level;
//                shape: the shape's index in the renderer's shape table (the traversal calls the
//                includer's hook for it; see shaders/bvh/traverse.glsl)
//       objectId: the scene node id (for the object-id output and picking)
//       flags  : bit 0 set: the transform mirrors (negative determinant): winding flips.
//
// Rays keep their world-space parameter t in every level: the local ray is
// (localFromWorld * origin, localFromWorld * direction) with the direction left unnormalised.
//
// Every buffer must fit GL_MAX_TEXTURE_BUFFER_SIZE texels (GL guarantees only 65,536):
// checkTextureBufferSizes() in size_check.h says which one does not.
#include <cstdint>

namespace glint::bvh {

inline constexpr int kNodeTexels = 1;
inline constexpr int kLevelTexels = 2;
inline constexpr int kTrianglePositionTexels = 3;
inline constexpr int kTriangleVertexTexels = 1;
inline constexpr int kInstanceTexels = 4;

inline constexpr std::uint32_t kInstanceMesh = 0;
inline constexpr std::uint32_t kInstanceShape = 1;
inline constexpr std::uint32_t kInstanceMirrored = 1u; // flags bit 0

inline constexpr std::uint32_t kMaxLeafTriangles = 8;
// The traversal packs a link into one int, (first << 4) | count: `first` stays below 2^27 (134 M
// nodes, triangle slots or instances; validation refuses more) and `count` below 16.
inline constexpr std::uint32_t kMaxLinkFirst = 1u << 27;
static_assert(kMaxLeafTriangles < 16);
// Traversal (GLSL and CPU): stack entries per level (one loop walks both levels on one stack of
// 2 * kStackSize entries, a mesh's above the top level's), and the cap on visited nodes over both
// levels, so a NaN ray or a corrupt buffer cannot loop forever. A level deeper than kStackSize is
// refused by validation on the CPU before upload.
inline constexpr int kStackSize = 64;
inline constexpr int kMaxTraversalSteps = 8192;

// Names of the sampler uniforms, for the renderer's glGetUniformLocation calls.
inline constexpr const char* kNodesUniform = "uBvhNodes";
inline constexpr const char* kLevelsUniform = "uBvhLevels";
inline constexpr const char* kTrianglePositionsUniform = "uBvhTrianglePositions";
inline constexpr const char* kTriangleVerticesUniform = "uBvhTriangleVertices";
inline constexpr const char* kInstancesUniform = "uBvhInstances";
inline constexpr const char* kTopLevelUniform = "uBvhTopLevel";

} // namespace glint::bvh
