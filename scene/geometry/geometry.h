#pragma once
// Geometry utilities the file loaders, the writer and the renderer share.
#include "scene/core/components.h"
#include "scene/core/mesh.h"

namespace glint {

// glTF: a primitive without NORMAL gets flat normals. Vertices are split per triangle so each
// face has its own normal (indices become 0..3n-1). Degenerate triangles get (0, 1, 0).
void generateFlatNormals(Primitive& p);

// MikkTSpace tangents (the convention glTF requires) from positions, normals, uv0 and indices.
// Returns false (and leaves tangents empty) when the primitive has no normals or no uv0.
bool generateTangents(Primitive& p);

// A triangle mesh standing in for an analytic shape in other tools (the glTF fallback mesh) and in
// the raster preview. `segments` controls smoothness of curved shapes; deterministic for a given input.
// GroundPlane becomes a large finite square (`groundExtent` metres across).
Primitive tessellateShape(const Shape& shape, int segments = 48, float groundExtent = 200.0f);

} // namespace glint
