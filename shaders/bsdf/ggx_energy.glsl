// Multiple-scattering compensation for the GGX lobes (Turquin 2019, "Practical multiple scattering
// compensation for microfacet models"): single scattering reflects E(mu, roughness) of the light when
// F = 1; the rest would leave after more bounces between microfacets. Scaling the lobe by
// 1 + F0 (1 - E) / E puts that energy back, tinted by F0. The scale depends on wo only, so the
// compensated BRDF is not exactly reciprocal (as in the paper). The Fresnel-weighted tables give
// what a rough specular layer reflects, which the diffuse beneath it must not reflect again.
#ifdef __cplusplus
#pragma once
#endif
#include "common/math.glsl"

// The tables, as renderer/cpu_twin/ggx_energy_tables.h holds and describes them: E(mu, roughness) of
// GGX with height-correlated masking and F = 1 (GGX_ALBEDO_TABLE) and the same integral with Fresnel
// weight (1 - wo.h)^5 (GGX_FRESNEL_ALBEDO_TABLE, so that a lobe with Schlick Fresnel reflects
// F0 E + (1 - F0) B, Karis 2013's split), 32 x 16 each: rows roughness = (i / 31)^2, columns
// mu = (j / 15)^2 (column 0 at mu = 0.002), dense at low roughness and grazing angles, where E changes
// fastest; and their cosine-weighted averages over mu, per roughness (32 entries each).
// C++ reads those arrays. GLSL reads the same floats from a uniform block that GpuScene uploads once,
// four entries per vec4 (std140), not from `const` arrays: NVIDIA's compiler took most of the path
// tracer's first link over constant tables indexed in every inlined copy of the BSDF
// (docs/PERFORMANCE.md, "Cold shader compile on NVIDIA").
#ifdef __cplusplus
float ggxAlbedoAt(int i) { return GGX_ALBEDO_TABLE[i]; }
float ggxFresnelAlbedoAt(int i) { return GGX_FRESNEL_ALBEDO_TABLE[i]; }
float ggxAverageAlbedoAt(int i) { return GGX_AVERAGE_ALBEDO_TABLE[i]; }
float ggxAverageFresnelAlbedoAt(int i) { return GGX_AVERAGE_FRESNEL_ALBEDO_TABLE[i]; }
#else
layout(std140) uniform GgxEnergyTables {
    vec4 uGgxAlbedo[128];
    vec4 uGgxFresnelAlbedo[128];
    vec4 uGgxAverageAlbedo[8];
    vec4 uGgxAverageFresnelAlbedo[8];
};
float ggxAlbedoAt(int i) { return uGgxAlbedo[i >> 2][i & 3]; }
float ggxFresnelAlbedoAt(int i) { return uGgxFresnelAlbedo[i >> 2][i & 3]; }
float ggxAverageAlbedoAt(int i) { return uGgxAverageAlbedo[i >> 2][i & 3]; }
float ggxAverageFresnelAlbedoAt(int i) { return uGgxAverageFresnelAlbedo[i >> 2][i & 3]; }
#endif

// Where (mu, roughness) falls in the 32 x 16 tables: the lower corner's index and the weights.
void ggxTableCoordinates(float mu, float roughness, OUT(int) index, OUT(vec2) t) {
    float x = sqrt(clamp(mu, 0.0f, 1.0f)) * 15.0f;
    float y = sqrt(clamp(roughness, 0.0f, 1.0f)) * 31.0f;
    int x0 = min(int(x), 14);
    int y0 = min(int(y), 30);
    index = y0 * 16 + x0;
    t = vec2(x - float(x0), y - float(y0));
}

float bilinear(float v00, float v01, float v10, float v11, vec2 t) {
    return mix(mix(v00, v01, t.x), mix(v10, v11, t.x), t.y);
}

// E(mu, roughness), bilinear.
float ggxDirectionalAlbedo(float mu, float roughness) {
    int i;
    vec2 t;
    ggxTableCoordinates(mu, roughness, i, t);
    return bilinear(ggxAlbedoAt(i), ggxAlbedoAt(i + 1), ggxAlbedoAt(i + 16), ggxAlbedoAt(i + 17), t);
}

float ggxFresnelAlbedo(float mu, float roughness) {
    int i;
    vec2 t;
    ggxTableCoordinates(mu, roughness, i, t);
    return bilinear(ggxFresnelAlbedoAt(i), ggxFresnelAlbedoAt(i + 1), ggxFresnelAlbedoAt(i + 16), ggxFresnelAlbedoAt(i + 17), t);
}

// Single-scattering albedo of a GGX lobe with Schlick Fresnel from f0, seen from mu.
vec3 ggxSchlickAlbedo(vec3 f0, float mu, float roughness) {
    return f0 * ggxDirectionalAlbedo(mu, roughness) + (vec3(1.0f) - f0) * ggxFresnelAlbedo(mu, roughness);
}

// Its cosine-weighted average over all directions.
vec3 ggxAverageSchlickAlbedo(vec3 f0, float roughness) {
    float y = sqrt(clamp(roughness, 0.0f, 1.0f)) * 31.0f;
    int i = min(int(y), 30);
    float t = y - float(i);
    float e = mix(ggxAverageAlbedoAt(i), ggxAverageAlbedoAt(i + 1), t);
    float b = mix(ggxAverageFresnelAlbedoAt(i), ggxAverageFresnelAlbedoAt(i + 1), t);
    return f0 * e + (vec3(1.0f) - f0) * b;
}

// The factor that restores the energy single scattering loses, for Fresnel reflectance f0.
vec3 ggxMultipleScatteringScale(vec3 f0, float mu, float roughness) {
    float e = max(ggxDirectionalAlbedo(mu, roughness), 0.05f);
    return vec3(1.0f) + f0 * ((1.0f - e) / e);
}
