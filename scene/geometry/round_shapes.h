#pragma once
// Tessellation of the curved analytic shapes, centred on the origin, +Y up, normals outward.
#include "primitive_builder.h"

namespace glint {

// A uv sphere: `segments` around the Y axis and segments / 2 (at least 2) rings pole to pole;
// no degenerate triangles at the poles.
void addSphere(PrimitiveBuilder& b, float radius, int segments);

// A closed cylinder along Y from -height/2 to +height/2 with two cap disks.
void addCylinder(PrimitiveBuilder& b, float radius, float height, int segments);

} // namespace glint
