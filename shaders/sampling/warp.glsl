// Maps from the unit square to directions and points, each with its density. Directions are in a
// local frame (+Z is the pole); pdfs are per unit solid angle (per unit area for the disk).
#ifdef __cplusplus
#pragma once
#endif
#include "common/math.glsl"

// Shirley-Chiu concentric mapping: keeps strata compact, unlike the polar (sqrt r) mapping.
vec2 concentricDisk(vec2 u) {
    float x = 2.0f * u.x - 1.0f;
    float y = 2.0f * u.y - 1.0f;
    if (x == 0.0f && y == 0.0f) return vec2(0.0f);
    bool xDominant = abs(x) > abs(y);
    float r = xDominant ? x : y;
    float theta = xDominant ? PI_OVER_FOUR * (y / x) : PI_OVER_TWO - PI_OVER_FOUR * (x / y);
    return r * vec2(cos(theta), sin(theta));
}

float concentricDiskPdf() { return INV_PI; }

vec3 cosineHemisphere(vec2 u) {
    vec2 d = concentricDisk(u);
    return vec3(d.x, d.y, safeSqrt(1.0f - d.x * d.x - d.y * d.y));
}

float cosineHemispherePdf(float cosTheta) { return max(cosTheta, 0.0f) * INV_PI; }

vec3 uniformSphere(vec2 u) {
    float z = 1.0f - 2.0f * u.x;
    float r = safeSqrt(1.0f - z * z);
    float phi = TWO_PI * u.y;
    return vec3(r * cos(phi), r * sin(phi), z);
}

float uniformSpherePdf() { return INV_FOUR_PI; }

// Directions within angle acos(cosMax) of +Z (sun disks, sphere lights).
vec3 uniformCone(vec2 u, float cosMax) {
    float cosTheta = mix(1.0f, cosMax, u.x);
    float sinTheta = safeSqrt(1.0f - cosTheta * cosTheta);
    float phi = TWO_PI * u.y;
    return vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
}

float uniformConePdf(float cosMax) { return 1.0f / (TWO_PI * (1.0f - cosMax)); }
