// The result of sampling a BSDF: a direction with its throughput weight.
#ifdef __cplusplus
#pragma once
#endif
#include "bsdf/material.glsl"

struct BsdfSample {
    vec3 wi;       // local frame
    vec3 weight;   // f * |cos(wi)| / pdf
    float pdf;     // per solid angle; for a delta lobe (LOBE_SPECULAR) the discrete probability
    uint lobe;     // LOBE_* flags
    float eta;     // relative IOR crossed by a refraction (n_wi side / n_wo side); 1 otherwise
};

BsdfSample noBsdfSample() { return BsdfSample(vec3(0.0f, 0.0f, 1.0f), vec3(0.0f), 0.0f, 0u, 1.0f); }

vec3 flipZ(vec3 v) { return vec3(v.x, v.y, -v.z); }

vec3 mirrorAboutNormal(vec3 w) { return vec3(-w.x, -w.y, w.z); }
