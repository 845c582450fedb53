// Bloom, down: the next level at half the size, each texel the 4x4 tent (1 3 3 1) / 8 per axis over
// the two source texels under it and their neighbours. The weights sum to 1, so the image's mean
// (its energy) is kept.
#include "bloom_sample.glsl"

uniform sampler2D uSource;

out vec4 outColor;

void main() {
    ivec2 corner = 2 * ivec2(gl_FragCoord.xy) - 1;
    const float w[4] = float[4](0.125, 0.375, 0.375, 0.125);
    vec4 sum = vec4(0.0);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) sum += w[x] * w[y] * fetchClamped(uSource, corner + ivec2(x, y));
    outColor = sum;
}
