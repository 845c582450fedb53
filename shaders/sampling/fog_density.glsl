// Optical depth and free-flight distances in an exponential height fog: extinction
// density x exp(-falloff x (y - base)) at height y (falloff 0: homogeneous), integrated in closed
// form along a ray, and inverted in closed form to sample where a ray scatters. `fog`: density
// (1/m), falloff (1/m), base height (m), unused.
#ifdef __cplusplus
#pragma once
#endif
#include "common/math.glsl"

float fogDensityAt(vec4 fog, float y) { return fog.x * exp(-fog.y * (y - fog.z)); }

// The optical depth from `origin` along unit `direction` over distance t >= 0. With the falloff
// a = falloff x direction.y, it is density(origin) x (1 - exp(-a t)) / a; for a t near 0 the
// quotient is taken from its series (GLSL has no expm1). An infinite depth (looking down through a
// falling fog, or far through a homogeneous one) comes out as inf or as a huge number.
float fogOpticalDepth(vec4 fog, vec3 origin, vec3 direction, float t) {
    float a = fog.y * direction.y;
    float x = a * t;
    float integral = abs(x) < 1e-3f ? t * (1.0f - x * (0.5f - x / 6.0f)) : (1.0f - exp(-x)) / a;
    return fogDensityAt(fog, origin.y) * integral;
}

// The distance at which the optical depth from `origin` reaches `tau`; `never` where it never does
// (a ray climbing out of a falling fog sees a finite depth). Inverse of fogOpticalDepth:
// t = -ln(1 - z) / a with z = a tau / density(origin).
float fogDistanceAtDepth(vec4 fog, vec3 origin, vec3 direction, float tau, float never) {
    float density = fogDensityAt(fog, origin.y);
    if (!(density > 0.0f)) return never;
    float a = fog.y * direction.y;
    float z = a * tau / density;
    if (z >= 1.0f) return never;
    float stretch = abs(z) < 1e-3f ? 1.0f + z * (0.5f + z / 3.0f) : -log(1.0f - z) / z;
    return min(tau / density * stretch, never);
}
