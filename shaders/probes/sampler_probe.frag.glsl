// Writes the first draws of each pixel's low-discrepancy stream (common/rng.glsl: rand1, rand2,
// rand3), so tests can compare the GPU's Owen-scrambled Sobol' points with the C++ twin's bit for
// bit (24-bit values are exact in a float).
#include "common/rng.glsl"

uniform uint uSampleIndex;
uniform uint uSeed;

out vec4 outValues;     // rand1, rand2.x, rand2.y, rand3.x
out vec4 outMoreValues; // rand3.y, rand3.z, rand4.x, rand4.w

void main() {
    Rng rng = rngStartLowDiscrepancy(uvec2(gl_FragCoord.xy), uSampleIndex, uSeed);
    float a = rand1(rng);
    vec2 b = rand2(rng);
    vec3 c = rand3(rng);
    vec4 d = rand4(rng);
    outValues = vec4(a, b, c.x);
    outMoreValues = vec4(c.y, c.z, d.x, d.w);
}
