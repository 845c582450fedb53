// Stateless random numbers keyed on (pixel, sample index, dimension, seed): any sample of any pixel
// can be recomputed alone, in any order, on the GPU or on the CPU twin. The hash is pcg4d
// (Jarzynski and Olano 2020, "Hash Functions for GPU Rendering"), 32-bit arithmetic only, which
// wraps identically in GLSL and in C++.
#ifdef __cplusplus
#pragma once
#endif
#include "common/compat.glsl"

uvec4 pcg4d(uvec4 v) {
    v = v * 1664525u + 1013904223u;
    v.x += v.y * v.w;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v.w += v.y * v.z;
    v = v ^ (v >> 16u);
    v.x += v.y * v.w;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v.w += v.y * v.z;
    return v;
}

// 24 random bits to [0, 1): float(x) * 2^-32 would round the top values up to 1.0.
float unitFloatFromBits(uint x) { return float(x >> 8u) * (1.0f / 16777216.0f); }

// A path's random stream: the hashed key of (pixel, sample, seed) and the next dimension to draw.
struct Rng {
    uvec4 key;
    uint dimension;
};

Rng rngStart(uvec2 pixel, uint sampleIndex, uint seed) {
    return Rng(pcg4d(uvec4(pixel.x, pixel.y, sampleIndex, seed)), 0u);
}

// Four independent 32-bit values for one dimension of a stream (the key's hash, shifted by dimension).
uvec4 rngBits(uvec4 key, uint dimension) {
    return pcg4d(uvec4(key.x, key.y, key.z, key.w + dimension));
}

float rand1(INOUT(Rng) r) {
    uvec4 bits = rngBits(r.key, r.dimension);
    r.dimension += 1u;
    return unitFloatFromBits(bits.x);
}

vec2 rand2(INOUT(Rng) r) {
    uvec4 bits = rngBits(r.key, r.dimension);
    r.dimension += 1u;
    return vec2(unitFloatFromBits(bits.x), unitFloatFromBits(bits.y));
}

vec3 rand3(INOUT(Rng) r) {
    uvec4 bits = rngBits(r.key, r.dimension);
    r.dimension += 1u;
    return vec3(unitFloatFromBits(bits.x), unitFloatFromBits(bits.y), unitFloatFromBits(bits.z));
}

vec4 rand4(INOUT(Rng) r) {
    uvec4 bits = rngBits(r.key, r.dimension);
    r.dimension += 1u;
    return vec4(unitFloatFromBits(bits.x), unitFloatFromBits(bits.y), unitFloatFromBits(bits.z),
                unitFloatFromBits(bits.w));
}
