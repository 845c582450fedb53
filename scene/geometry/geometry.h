#pragma once
// Geometry utilities the file loaders, the writer and the renderer share.
#include "scene/core/components.h"
#include "scene/core/mesh.h"

namespace glint {

// glTF: a primitive without NORMAL gets flat normals. Vertices are split per triangle so each
// face has its own normal (indices become 0..3n-1); other attributes follow their corners and
// tangents are dropped. Degenerate triangles get (0, 1, 0). An index out of range throws
// std::out_of_range.
void generateFlatNormals(Primitive& p);

// MikkTSpace tangents (the convention glTF requires) from positions, normals, uv0 and indices
// (see mikktspace.h for the algorithm). glTF's v axis points down the image, so w is the
// MikkTSpace sign negated: bitangent = cross(normal, tangent) * w points towards decreasing v.
// Where corners of one vertex get different tangents (uv mirror seams) the vertex is split, so
// positions and indices may grow. Returns false (and leaves tangents empty) when the primitive has
// no normals or no uv0, an index out of range, or non-finite attributes.
bool generateTangents(Primitive& p);

// A triangle mesh standing in for an analytic shape in other tools (the glTF fallback mesh) and in
// the raster preview. `segments` (clamped to [3, 4096]) controls smoothness of curved shapes;
// deterministic for a given input. GroundPlane becomes a large finite square (`groundExtent`
// metres across). Normals point outward, triangles are counter-clockwise seen from outside, uv0
// and MikkTSpace tangents are filled, and shared rims and seams are bit-identical (watertight).
// Sphere: a uv sphere, `segments` around Y and segments / 2 rings; Cylinder: closed by two caps.
Primitive tessellateShape(const Shape& shape, int segments = 48, float groundExtent = 200.0f);

} // namespace glint
