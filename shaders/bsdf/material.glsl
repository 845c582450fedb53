// A surface's material at a hit, after texture lookups: the glTF metallic-roughness model with
// KHR_materials_specular, _transmission, _ior and _volume. The BSDF code reads only this struct.
#ifdef __cplusplus
#pragma once
#endif
#include "common/math.glsl"

struct SurfaceMaterial {
    vec3 baseColor;
    float metallic;
    float roughness;          // perceptual; GGX alpha = roughness^2
    float specularFactor;     // KHR_materials_specular; 0 = pure Lambert for a dielectric
    vec3 specularColor;
    float transmission;       // KHR_materials_transmission
    float ior;
    bool thinWalled;          // no volume thickness: transmission passes straight through
    vec3 attenuationColor;    // KHR_materials_volume
    float attenuationDistance; // metres; <= 0 means no absorption
    float thickness;
};

// The glTF default material (white, rough dielectric, no transmission).
SurfaceMaterial defaultSurfaceMaterial() {
    return SurfaceMaterial(vec3(1.0f), 0.0f, 1.0f, 1.0f, vec3(1.0f), 0.0f, 1.5f, true, vec3(1.0f), 0.0f, 0.0f);
}

// Beer-Lambert absorption coefficient per metre inside a refracting volume (0 where none is set).
vec3 attenuationCoefficient(SurfaceMaterial m) {
    if (m.attenuationDistance <= 0.0f) return vec3(0.0f);
    vec3 c = max(m.attenuationColor, vec3(1e-6f));
    return -log(c) / m.attenuationDistance;
}

// Lobe flags of a sampled direction (BsdfSample.lobe), combinable with |.
const uint LOBE_DIFFUSE = 1u;
const uint LOBE_GLOSSY = 2u;
const uint LOBE_SPECULAR = 4u;     // a delta lobe: pdf is a discrete probability, not a density
const uint LOBE_TRANSMISSION = 8u;
