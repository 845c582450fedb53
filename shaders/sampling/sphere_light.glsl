// Lights with extent as seen from a point: a sphere lamp (a sphere of uniform radiance) and a sun
// disk (a cone of directions of uniform radiance). Both are sampled uniformly over the cone they
// subtend (sampling/warp.glsl uniformCone) and found by BSDF-sampled rays, so light sampling and
// ray hits must agree on the cone, its pdf and the radiance: they share these functions.
#ifdef __cplusplus
#pragma once
#endif
#include "common/math.glsl"

// 1 - cos(asin(sqrt(sin2))) without cancellation for small sin2.
float oneMinusCosFromSin2(float sin2) { return sin2 / (1.0f + sqrt(max(1.0f - sin2, 0.0f))); }

// 1 - cos of the half angle of the cone a sphere of radius r subtends at distance d (> r) from its
// centre: sin^2 = r^2 / d^2.
float sphereConeOneMinusCos(float radius, float distance2) { return oneMinusCosFromSin2(radius * radius / distance2); }

// Solid-angle pdf of uniform sampling over a cone given by 1 - cos of its half angle.
float conePdfFromOneMinusCos(float oneMinusCos) { return 1.0f / (TWO_PI * oneMinusCos); }

// Radiance of a sphere lamp of radiant intensity I and radius r: I / (pi r^2), so that far away it
// has the intensity of the point light (its projected area is pi r^2), and its irradiance on a plane
// facing it at any distance d > r is exactly I / d^2.
vec3 sphereLampRadiance(vec3 intensity, float radius) { return intensity / (PI * radius * radius); }

// Distance along a unit direction from `origin` to the sphere's near surface when the ray starts
// outside the sphere and hits it before tMax; -1 otherwise (a point inside a lamp does not see it,
// as light sampling treats it as the delta light there).
float hitSphereFromOutside(vec3 origin, vec3 direction, vec3 centre, float radius, float tMax) {
    vec3 offset = centre - origin;
    float along = dot(offset, direction);
    float distance2 = dot(offset, offset);
    float radius2 = radius * radius;
    if (!(distance2 > radius2) || along <= 0.0f) return -1.0f;
    // Squared distance of the centre from the ray, from the perpendicular part (no cancellation of
    // distance2 - along^2 when the lamp is far).
    vec3 perpendicular = offset - along * direction;
    float h2 = radius2 - dot(perpendicular, perpendicular);
    if (h2 < 0.0f) return -1.0f;
    float t = along - sqrt(h2);
    return t > 0.0f && t < tMax ? t : -1.0f;
}
