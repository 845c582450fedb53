#pragma once
// Area lights as emitting surfaces (docs/LIGHTS.md): the analytic shape an area light is, where it
// sits in the light's space, its area and its radiance. The renderer traces that shape as an
// emitter, and the glTF writer writes it as an emissive mesh for other tools, so both use these.
#include "scene/core/components.h"

#include <glm/glm.hpp>

namespace glint {

// The emitter as an analytic shape in its own space: a rectangle (quad) or disk in the XZ plane
// facing +Y, or a sphere.
Shape areaLightShape(const Light& light);

// Shape space to the light's space: a rectangle or disk turns so that it faces the light's -Z
// (the quad's X stays X, its Z becomes the light's Y); a sphere stays as it is.
glm::mat4 lightFromAreaShape(const Light& light);

// Outer surface area of a shape under an affine map (square metres): exact for planar faces under
// any map and for round shapes under a similarity, a fine quadrature otherwise; 0 for the infinite
// ground plane.
float shapeArea(const Shape& shape, const glm::mat4& worldFromShape);

// The emitting area of an area light placed by `worldFromLight` (its node's world transform).
float areaLightArea(const Light& light, const glm::mat4& worldFromLight);

// Radiance of an area light of power P watts over `area` square metres: P / (pi A) x colour, the
// radiance of a Lambertian emitter whose flux (out of its emitting side) is P. 0 for no area.
glm::vec3 areaLightRadiance(const Light& light, float area);

} // namespace glint
