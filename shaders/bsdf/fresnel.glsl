// Fresnel reflectance: Schlick's approximation for the glTF lobes, the exact unpolarised form for
// refracting dielectrics (needed for total internal reflection).
#ifdef __cplusplus
#pragma once
#endif
#include "common/math.glsl"

vec3 fresnelSchlick(vec3 f0, float cosTheta) {
    float m = clamp(1.0f - cosTheta, 0.0f, 1.0f);
    float m2 = m * m;
    return f0 + (vec3(1.0f) - f0) * (m2 * m2 * m);
}

// cosI: cosine on the incident side (> 0); eta = n_transmitted / n_incident. 1 under total internal
// reflection.
float fresnelDielectric(float cosI, float eta) {
    float sin2T = (1.0f - cosI * cosI) / (eta * eta);
    if (sin2T >= 1.0f) return 1.0f;
    float cosT = safeSqrt(1.0f - sin2T);
    float rs = (cosI - eta * cosT) / (cosI + eta * cosT);
    float rp = (eta * cosI - cosT) / (eta * cosI + cosT);
    return 0.5f * (rs * rs + rp * rp);
}

// KHR_materials_specular: F0 of the dielectric layer from the IOR, tinted and clamped.
vec3 dielectricF0(float ior, vec3 specularColor) {
    float r = (ior - 1.0f) / (ior + 1.0f);
    return min(r * r * specularColor, vec3(1.0f));
}
