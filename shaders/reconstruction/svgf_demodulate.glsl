// Demodulation by the first hit's albedo (diffuse + specular lobes: a metal's base colour is its
// specular albedo, its diffuse albedo is ~0), so the filters blur lighting and never texture
// detail; channels with (almost) no albedo keep their radiance (nothing to factor out).
const float MIN_ALBEDO = 1.0e-3;

vec3 demodulate(vec3 radiance, vec3 albedo) {
    return mix(radiance, radiance / max(albedo, vec3(MIN_ALBEDO)), greaterThan(albedo, vec3(MIN_ALBEDO)));
}

vec3 remodulate(vec3 illumination, vec3 albedo) {
    return mix(illumination, illumination * albedo, greaterThan(albedo, vec3(MIN_ALBEDO)));
}

vec3 lobeAlbedo(sampler2D diffuse, sampler2D specular, ivec2 pixel) {
    return texelFetch(diffuse, pixel, 0).rgb + texelFetch(specular, pixel, 0).rgb;
}
