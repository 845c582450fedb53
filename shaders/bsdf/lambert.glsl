// Lambert diffuse reflection in the local frame: f = albedo / pi, sampled by the cosine.
#ifdef __cplusplus
#pragma once
#endif
#include "sampling/warp.glsl"

// f * cos(wi) per unit albedo.
float lambertReflection(vec3 wo, vec3 wi) { return wo.z > 0.0f && wi.z > 0.0f ? wi.z * INV_PI : 0.0f; }

float lambertPdf(vec3 wo, vec3 wi) { return wo.z > 0.0f ? cosineHemispherePdf(wi.z) : 0.0f; }

vec3 sampleLambert(vec2 u) { return cosineHemisphere(u); }
