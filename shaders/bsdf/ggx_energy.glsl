// Multiple-scattering compensation for the GGX lobes (Turquin 2019, "Practical multiple scattering
// compensation for microfacet models"): single scattering reflects E(mu, roughness) of the light when
// F = 1; the rest would leave after more bounces between microfacets. Scaling the lobe by
// 1 + F0 (1 - E) / E puts that energy back, tinted by F0. The scale depends on wo only, so the
// compensated BRDF is not exactly reciprocal (as in the paper).
#ifdef __cplusplus
#pragma once
#endif
#include "common/math.glsl"

// E(mu, roughness) of GGX with height-correlated masking and F = 1, rows roughness = i / 15,
// columns mu = (j / 15)^2 (column 0 at mu = 0.002): dense at grazing angles, where E changes
// fastest. Made by VNDF sampling with 256 x 256 strata; test_twin_furnace recomputes it.
FLOAT_TABLE(GGX_ALBEDO_TABLE, 256)(
    0.9136f, 0.9705f, 0.9982f, 0.9998f, 1.0000f, 1.0000f, 1.0000f, 1.0000f, 1.0000f, 1.0000f, 1.0000f, 1.0000f, 1.0000f, 1.0000f, 1.0000f, 1.0000f,
    0.9245f, 0.8921f, 0.9646f, 0.9928f, 0.9979f, 0.9995f, 0.9998f, 0.9999f, 0.9999f, 1.0000f, 1.0000f, 1.0000f, 1.0000f, 1.0000f, 1.0000f, 1.0000f,
    0.9772f, 0.9526f, 0.8920f, 0.9221f, 0.9645f, 0.9846f, 0.9928f, 0.9962f, 0.9979f, 0.9987f, 0.9996f, 0.9998f, 0.9999f, 0.9999f, 1.0000f, 1.0000f,
    0.9896f, 0.9772f, 0.9243f, 0.8910f, 0.9049f, 0.9377f, 0.9639f, 0.9794f, 0.9878f, 0.9925f, 0.9951f, 0.9968f, 0.9977f, 0.9982f, 0.9988f, 0.9998f,
    0.9939f, 0.9863f, 0.9496f, 0.9091f, 0.8879f, 0.8948f, 0.9179f, 0.9423f, 0.9610f, 0.9737f, 0.9818f, 0.9869f, 0.9902f, 0.9925f, 0.9938f, 0.9953f,
    0.9955f, 0.9901f, 0.9632f, 0.9281f, 0.8970f, 0.8814f, 0.8849f, 0.9011f, 0.9216f, 0.9404f, 0.9553f, 0.9662f, 0.9738f, 0.9792f, 0.9830f, 0.9858f,
    0.9961f, 0.9913f, 0.9692f, 0.9392f, 0.9079f, 0.8829f, 0.8703f, 0.8714f, 0.8828f, 0.8994f, 0.9167f, 0.9322f, 0.9448f, 0.9546f, 0.9620f, 0.9676f,
    0.9960f, 0.9912f, 0.9710f, 0.9435f, 0.9132f, 0.8850f, 0.8637f, 0.8523f, 0.8515f, 0.8592f, 0.8723f, 0.8876f, 0.9027f, 0.9163f, 0.9278f, 0.9371f,
    0.9956f, 0.9907f, 0.9700f, 0.9427f, 0.9125f, 0.8825f, 0.8563f, 0.8366f, 0.8253f, 0.8225f, 0.8270f, 0.8368f, 0.8497f, 0.8637f, 0.8774f, 0.8900f,
    0.9948f, 0.9896f, 0.9672f, 0.9383f, 0.9064f, 0.8743f, 0.8444f, 0.8189f, 0.7995f, 0.7872f, 0.7821f, 0.7833f, 0.7896f, 0.7996f, 0.8116f, 0.8245f,
    0.9938f, 0.9881f, 0.9630f, 0.9310f, 0.8962f, 0.8608f, 0.8271f, 0.7966f, 0.7707f, 0.7504f, 0.7361f, 0.7280f, 0.7255f, 0.7278f, 0.7340f, 0.7430f,
    0.9927f, 0.9862f, 0.9575f, 0.9215f, 0.8826f, 0.8430f, 0.8047f, 0.7692f, 0.7374f, 0.7101f, 0.6879f, 0.6708f, 0.6590f, 0.6520f, 0.6495f, 0.6507f,
    0.9917f, 0.9839f, 0.9512f, 0.9104f, 0.8663f, 0.8216f, 0.7782f, 0.7373f, 0.6998f, 0.6662f, 0.6368f, 0.6120f, 0.5915f, 0.5754f, 0.5634f, 0.5552f,
    0.9905f, 0.9815f, 0.9441f, 0.8978f, 0.8481f, 0.7976f, 0.7485f, 0.7019f, 0.6587f, 0.6192f, 0.5837f, 0.5521f, 0.5244f, 0.5005f, 0.4801f, 0.4631f,
    0.9891f, 0.9789f, 0.9364f, 0.8842f, 0.8282f, 0.7716f, 0.7165f, 0.6642f, 0.6154f, 0.5706f, 0.5296f, 0.4926f, 0.4593f, 0.4295f, 0.4030f, 0.3794f,
    0.9877f, 0.9760f, 0.9282f, 0.8697f, 0.8071f, 0.7441f, 0.6830f, 0.6251f, 0.5712f, 0.5215f, 0.4762f, 0.4350f, 0.3978f, 0.3642f, 0.3340f, 0.3069f);

const int GGX_ALBEDO_TABLE_SIZE = 16;

float ggxAlbedoTableAt(int roughnessIndex, int muIndex) {
    return GGX_ALBEDO_TABLE[roughnessIndex * GGX_ALBEDO_TABLE_SIZE + muIndex];
}

// Bilinear lookup of E(mu, roughness).
float ggxDirectionalAlbedo(float mu, float roughness) {
    float x = sqrt(clamp(mu, 0.0f, 1.0f)) * 15.0f;
    float y = clamp(roughness, 0.0f, 1.0f) * 15.0f;
    int x0 = min(int(x), 14);
    int y0 = min(int(y), 14);
    float tx = x - float(x0);
    float ty = y - float(y0);
    float top = mix(ggxAlbedoTableAt(y0, x0), ggxAlbedoTableAt(y0, x0 + 1), tx);
    float bottom = mix(ggxAlbedoTableAt(y0 + 1, x0), ggxAlbedoTableAt(y0 + 1, x0 + 1), tx);
    return mix(top, bottom, ty);
}

// The factor that restores the energy single scattering loses, for Fresnel reflectance f0.
vec3 ggxMultipleScatteringScale(vec3 f0, float mu, float roughness) {
    float e = max(ggxDirectionalAlbedo(mu, roughness), 0.05f);
    return vec3(1.0f) + f0 * ((1.0f - e) / e);
}
