// A hit's material, unpacked from the material buffer (layout: renderer/gpu_scene/packed_scene.cpp)
// into the shared BSDF's SurfaceMaterial, plus its emission.
#include "bsdf/material.glsl"

SurfaceMaterial fetchSurfaceMaterial(int material) {
    vec4 base = materialTexel(material, 0);
    vec4 emissionRoughness = materialTexel(material, 1);
    vec4 metallicSpecularTransmissionIor = materialTexel(material, 2);
    vec4 specularColorThickness = materialTexel(material, 3);
    vec4 attenuation = materialTexel(material, 4);
    return SurfaceMaterial(base.rgb, metallicSpecularTransmissionIor.x, emissionRoughness.w,
                           metallicSpecularTransmissionIor.y, specularColorThickness.rgb,
                           metallicSpecularTransmissionIor.z, metallicSpecularTransmissionIor.w,
                           specularColorThickness.w <= 0.0, attenuation.rgb, attenuation.w, specularColorThickness.w);
}

// Radiance emitted from both sides: emissiveFactor x emissiveStrength, 1:1 (no photometric scale).
vec3 fetchEmission(int material) {
    return materialTexel(material, 1).rgb;
}
