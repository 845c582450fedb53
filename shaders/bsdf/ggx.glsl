// GGX (Trowbridge-Reitz) microfacets in the local frame (normal = +Z) with height-correlated Smith
// masking-shadowing (Heitz 2014) and visible-normal sampling (Heitz 2018, "Sampling the GGX
// Distribution of Visible Normals"). alpha = perceptual roughness squared.
#ifdef __cplusplus
#pragma once
#endif
#include "common/math.glsl"

// Below this alpha a lobe is treated as a perfect mirror (delta), where the density overflows floats.
const float GGX_DELTA_ALPHA = 1e-3f;

float ggxAlphaFromRoughness(float roughness) { return max(roughness * roughness, 0.0f); }

// Written with sin^2 = x^2 + y^2 rather than 1 - z^2: near the peak of a low-roughness lobe the
// difference 1 - z^2 loses most of its float digits.
float ggxD(vec3 h, float alpha) {
    if (h.z <= 0.0f) return 0.0f;
    float a2 = alpha * alpha;
    float d = h.x * h.x + h.y * h.y + a2 * h.z * h.z;
    return a2 / (PI * d * d);
}

float ggxLambda(vec3 w, float alpha) {
    float c2 = w.z * w.z;
    if (c2 <= 0.0f) return 1e30f;
    float t2 = (w.x * w.x + w.y * w.y) / c2;
    return 0.5f * (-1.0f + sqrt(1.0f + alpha * alpha * t2));
}

float ggxG1(vec3 w, float alpha) { return 1.0f / (1.0f + ggxLambda(w, alpha)); }

float ggxG2(vec3 wo, vec3 wi, float alpha) {
    return 1.0f / (1.0f + ggxLambda(wo, alpha) + ggxLambda(wi, alpha));
}

// Density of visible normals seen from wo (wo.z > 0): G1(wo) max(0, wo.h) D(h) / wo.z.
float ggxVisibleNormalPdf(vec3 wo, vec3 h, float alpha) {
    float cosOH = dot(wo, h);
    if (cosOH <= 0.0f || wo.z <= 0.0f) return 0.0f;
    return ggxG1(wo, alpha) * cosOH * ggxD(h, alpha) / wo.z;
}

// A microfacet normal visible from wo (wo.z > 0), density ggxVisibleNormalPdf.
vec3 sampleGgxVisibleNormal(vec3 wo, float alpha, vec2 u) {
    vec3 v = normalize(vec3(alpha * wo.x, alpha * wo.y, wo.z));
    float lensq = v.x * v.x + v.y * v.y;
    vec3 t1 = lensq > 0.0f ? vec3(-v.y, v.x, 0.0f) * inversesqrt(lensq) : vec3(1.0f, 0.0f, 0.0f);
    vec3 t2 = cross(v, t1);
    float r = sqrt(u.x);
    float phi = TWO_PI * u.y;
    float p1 = r * cos(phi);
    float p2 = r * sin(phi);
    float s = 0.5f * (1.0f + v.z);
    p2 = (1.0f - s) * safeSqrt(1.0f - p1 * p1) + s * p2;
    vec3 n = p1 * t1 + p2 * t2 + safeSqrt(1.0f - p1 * p1 - p2 * p2) * v;
    return normalize(vec3(alpha * n.x, alpha * n.y, max(n.z, 1e-7f)));
}

// pdf of wi = reflect(-wo, h) when h is a visible normal: D_vis(h) / (4 wo.h).
float ggxReflectionPdf(vec3 wo, vec3 wi, float alpha) {
    vec3 h = normalize(wo + wi);
    float cosOH = dot(wo, h);
    return cosOH > 0.0f ? ggxVisibleNormalPdf(wo, h, alpha) / (4.0f * cosOH) : 0.0f;
}

// Microfacet reflection f * cos(wi) without Fresnel (both directions above the surface).
float ggxReflectionNoFresnel(vec3 wo, vec3 wi, float alpha) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    vec3 h = normalize(wo + wi);
    return ggxD(h, alpha) * ggxG2(wo, wi, alpha) / (4.0f * wo.z);
}
