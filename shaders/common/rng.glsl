// Stateless random numbers keyed on (pixel, sample index, dimension, seed): any sample of any pixel
// can be recomputed alone, in any order, on the GPU or on the CPU twin. Two streams, both 32-bit
// integer arithmetic only, which wraps identically in GLSL and in C++:
// - independent: the hash pcg4d (Jarzynski and Olano 2020, "Hash Functions for GPU Rendering") of
//   (pixel, sample, seed) and the dimension (rngStart);
// - low-discrepancy: Owen-scrambled Sobol' points with hash-based scrambling (Burley 2020,
//   "Practical Hash-based Owen Scrambling"), keyed on (pixel, seed), indexed by the sample and
//   padded across dimensions (rngStartLowDiscrepancy). Each draw is its own dimension: its 2D part
//   comes from Sobol' dimensions 0 and 1 (a (0,2)-sequence: the first 2^k samples of a pixel put one
//   point in every elementary interval of area 2^-k), through a sample order shuffled per pixel
//   and draw, so that draws do not correlate; a draw's other components are 1D (0,1)-sequences
//   shuffled likewise.
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

// A path's random stream: the hashed key of (pixel, sample, seed) and the next dimension to draw;
// for the low-discrepancy stream also the sample's index and the pixel's scrambling key.
struct Rng {
    uvec4 key;         // pcg4d(pixel, sample, seed): the independent stream, and per-sample bits
    uint dimension;
    bool lowDiscrepancy;
    uint sampleIndex;  // low-discrepancy: the point's index in the pixel's sequence
    uvec4 scrambleKey; // low-discrepancy: pcg4d of (pixel, seed), the same for every sample
};

Rng rngStart(uvec2 pixel, uint sampleIndex, uint seed) {
    return Rng(pcg4d(uvec4(pixel.x, pixel.y, sampleIndex, seed)), 0u, false, sampleIndex, uvec4(0u));
}

// Four independent 32-bit values for one dimension of a stream (the key's hash, shifted by dimension).
uvec4 rngBits(uvec4 key, uint dimension) {
    return pcg4d(uvec4(key.x, key.y, key.z, key.w + dimension));
}

// The low-discrepancy stream of a pixel. The scrambling key leaves out the sample index, so all
// samples of a pixel are points of one scrambled sequence.
Rng rngStartLowDiscrepancy(uvec2 pixel, uint sampleIndex, uint seed) {
    return Rng(pcg4d(uvec4(pixel.x, pixel.y, sampleIndex, seed)), 0u, true, sampleIndex,
               pcg4d(uvec4(pixel.x, pixel.y, seed, 0x50b01u)));
}

// Laine and Karras' permutation as improved by Vegdahl ("Building a better LK hash", 2021): each
// bit of x is flipped by a hash of the seed and of the bits below it only.
uint laineKarrasPermutation(uint x, uint seed) {
    x ^= x * 0x3d20adeau;
    x += seed;
    x *= (seed >> 16u) | 1u;
    x ^= x * 0x05526c56u;
    x ^= x * 0x53a22864u;
    return x;
}

// Owen scrambling of a 32-bit binary fraction (bit 31 is 1/2): each digit is flipped by a hash of
// the seed and the digits above it. Applied to a sample index, a shuffle that maps the first 2^k
// indices onto an aligned block of 2^k (which, for Sobol' points, is again a net).
uint nestedUniformScramble(uint x, uint seed) {
    return bitfieldReverse(laineKarrasPermutation(bitfieldReverse(x), seed));
}

// Sobol' dimension 1 as a binary fraction. Its generator matrix is Pascal's triangle mod 2: digit
// q + 1 of the point is the XOR of the index bits j whose binary digits include q's (Lucas'
// theorem), a superset sum over 5-bit positions done in five steps. Dimension 0 is
// bitfieldReverse(index) (van der Corput).
uint sobolDimension1(uint index) {
    uint z = index;
    z ^= (z >> 1u) & 0x55555555u;
    z ^= (z >> 2u) & 0x33333333u;
    z ^= (z >> 4u) & 0x0f0f0f0fu;
    z ^= (z >> 8u) & 0x00ff00ffu;
    z ^= (z >> 16u) & 0x0000ffffu;
    return bitfieldReverse(z);
}

// A bijective 32-bit mixer (Wellons' lowbias32): a further seed from one already drawn.
uint mixBits(uint x) {
    x ^= x >> 16u;
    x *= 0x7feb352du;
    x ^= x >> 15u;
    x *= 0x846ca68bu;
    x ^= x >> 16u;
    return x;
}

// One scrambled point of the 1D sequence (Owen-scrambled van der Corput), sample order shuffled.
uint sobol1D(uint index, uint shuffleSeed, uint scrambleSeed) {
    uint shuffled = nestedUniformScramble(index, shuffleSeed);
    return bitfieldReverse(laineKarrasPermutation(shuffled, scrambleSeed)); // scrambled bitfieldReverse(shuffled)
}

// One scrambled point of the 2D (0,2)-sequence, sample order shuffled.
uvec2 sobol2D(uint index, uint shuffleSeed, uint scrambleX, uint scrambleY) {
    uint shuffled = nestedUniformScramble(index, shuffleSeed);
    return uvec2(bitfieldReverse(laineKarrasPermutation(shuffled, scrambleX)),
                 nestedUniformScramble(sobolDimension1(shuffled), scrambleY));
}

// A draw's hash: the independent stream's four values, or the low-discrepancy stream's seeds.
uvec4 drawBits(Rng r) { return rngBits(r.lowDiscrepancy ? r.scrambleKey : r.key, r.dimension); }

float rand1(INOUT(Rng) r) {
    uvec4 bits = drawBits(r);
    uint x = r.lowDiscrepancy ? sobol1D(r.sampleIndex, bits.x, bits.y) : bits.x;
    r.dimension += 1u;
    return unitFloatFromBits(x);
}

vec2 rand2(INOUT(Rng) r) {
    uvec4 bits = drawBits(r);
    uvec2 xy = r.lowDiscrepancy ? sobol2D(r.sampleIndex, bits.x, bits.y, bits.z) : uvec2(bits.x, bits.y);
    r.dimension += 1u;
    return vec2(unitFloatFromBits(xy.x), unitFloatFromBits(xy.y));
}

// (a choice, a 2D point): where a 3D draw picks a lobe or a light and then a direction or point, the
// 2D part (y, z) is the (0,2)-sequence and x a 1D sequence of its own.
vec3 rand3(INOUT(Rng) r) {
    uvec4 bits = drawBits(r);
    uvec3 xyz = uvec3(bits.x, bits.y, bits.z);
    if (r.lowDiscrepancy) {
        uvec2 yz = sobol2D(r.sampleIndex, bits.x, bits.y, bits.z);
        xyz = uvec3(sobol1D(r.sampleIndex, bits.w, mixBits(bits.w)), yz.x, yz.y);
    }
    r.dimension += 1u;
    return vec3(unitFloatFromBits(xyz.x), unitFloatFromBits(xyz.y), unitFloatFromBits(xyz.z));
}

// Two 2D points: (x, y) and (z, w) each from the (0,2)-sequence, shuffled apart.
vec4 rand4(INOUT(Rng) r) {
    uvec4 bits = drawBits(r);
    uvec4 xyzw = bits;
    if (r.lowDiscrepancy) {
        uint w = mixBits(bits.w);
        xyzw = uvec4(sobol2D(r.sampleIndex, bits.x, bits.y, bits.z), sobol2D(r.sampleIndex, bits.w, w, mixBits(w)));
    }
    r.dimension += 1u;
    return vec4(unitFloatFromBits(xyzw.x), unitFloatFromBits(xyzw.y), unitFloatFromBits(xyzw.z),
                unitFloatFromBits(xyzw.w));
}
