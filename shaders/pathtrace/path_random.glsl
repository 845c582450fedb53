// Random numbers keyed on (pixel, sample index, dimension, seed): no state carried between
// samples, so any sample of any pixel can be recomputed alone. 32-bit PCG hash (Jarzynski and
// Olano, "Hash Functions for GPU Rendering"); its CPU twin is renderer/path_random_twin.h.

uint pcgHash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// 24 random bits to [0, 1): float(x) * 2^-32 could round up to 1.0.
float uintToUnit(uint x) {
    return float(x >> 8u) * (1.0 / 16777216.0);
}

struct PathRandom {
    uint key;       // hash of pixel, sample and seed
    uint dimension; // next dimension to draw
};

uint pathKey(uvec2 pixel, uint sampleIndex, uint seed) {
    return pcgHash(pixel.x ^ pcgHash(pixel.y ^ pcgHash(sampleIndex ^ pcgHash(seed))));
}

PathRandom pathRandom(uvec2 pixel, uint sampleIndex, uint seed) {
    return PathRandom(pathKey(pixel, sampleIndex, seed), 0u);
}

uint hashDimension(uint key, uint dimension) {
    return pcgHash(key ^ pcgHash(dimension + 0x9e3779b9u));
}

float next1D(INOUT(PathRandom) r) {
    float u = uintToUnit(hashDimension(r.key, r.dimension));
    r.dimension += 1u;
    return u;
}

vec2 next2D(INOUT(PathRandom) r) {
    float a = next1D(r);
    return vec2(a, next1D(r));
}
