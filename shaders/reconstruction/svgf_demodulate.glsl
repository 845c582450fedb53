// Demodulation of each lobe by its own albedo (shaders/pathtrace/albedo_split.glsl): the diffuse
// part of the radiance by the diffuse albedo, the specular part (metal, the dielectric layer, glass)
// by the specular albedo, so the filters blur lighting and never texture detail. Channels with
// (almost) no albedo keep their radiance (nothing to factor out; e.g. an emitter's diffuse part on a metal).
#include "reconstruction/common.glsl"

const float MIN_ALBEDO = 1.0e-3;

vec3 demodulate(vec3 radiance, vec3 albedo) {
    return mix(radiance, radiance / max(albedo, vec3(MIN_ALBEDO)), greaterThan(albedo, vec3(MIN_ALBEDO)));
}

vec3 remodulate(vec3 illumination, vec3 albedo) {
    return mix(illumination, illumination * albedo, greaterThan(albedo, vec3(MIN_ALBEDO)));
}

// The path tracer's radiance and its specular part (path_trace_pass.h): the diffuse part is the
// rest. Guarded: NaN, Inf and negative values become 0, the specular part never exceeds the whole.
void splitRadiance(vec3 radiance, vec3 specular, out vec3 diffusePart, out vec3 specularPart) {
    vec3 r = finiteRadiance(radiance);
    specularPart = min(finiteRadiance(specular), r);
    diffusePart = r - specularPart;
}

// Both lobes' albedo: demodulates the whole radiance where one signal is wanted (anti-lag).
vec3 lobeAlbedo(sampler2D diffuse, sampler2D specular, ivec2 pixel) {
    return texelFetch(diffuse, pixel, 0).rgb + texelFetch(specular, pixel, 0).rgb;
}
