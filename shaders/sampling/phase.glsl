// The Henyey-Greenstein phase function of participating media, as a density over the sphere of
// scattered directions (1/sr). `cosTheta` is measured from the direction the light was travelling:
// g > 0 scatters forward, g < 0 back, g = 0 evenly.
#ifdef __cplusplus
#pragma once
#endif
#include "common/math.glsl"
#include "common/frame.glsl"

float henyeyGreenstein(float cosTheta, float g) {
    float denominator = 1.0f + g * g - 2.0f * g * cosTheta;
    return INV_FOUR_PI * (1.0f - g * g) / (denominator * sqrt(max(denominator, 1e-12f)));
}

// The cosine of a scattering angle drawn in proportion to henyeyGreenstein, by inverting its CDF;
// near g = 0 the inversion loses precision, and the lobe is uniform there anyway.
float sampleHenyeyGreensteinCos(float g, float u) {
    if (abs(g) < 1e-3f) return 1.0f - 2.0f * u;
    float s = (1.0f - g * g) / (1.0f - g + 2.0f * g * u);
    return clamp((1.0f + g * g - s * s) / (2.0f * g), -1.0f, 1.0f);
}

// A scattered direction (world space) for light that was travelling along `travel`; `pdf` is the
// phase function's value there, which is also the sample's weight's denominator: phase / pdf = 1.
vec3 sampleHenyeyGreenstein(vec3 travel, float g, vec2 u, OUT(float) pdf) {
    float cosTheta = sampleHenyeyGreensteinCos(g, u.x);
    float sinTheta = safeSqrt(1.0f - cosTheta * cosTheta);
    float phi = TWO_PI * u.y;
    pdf = henyeyGreenstein(cosTheta, g);
    return worldFromLocal(frameFromNormal(travel), vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta));
}
