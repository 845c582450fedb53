// Writes the first four random numbers of each pixel's stream (common/rng.glsl), so tests can
// compare the GPU's hash with its C++ twin bit for bit (24-bit values are exact in a float).
#include "common/rng.glsl"

uniform uint uSampleIndex;
uniform uint uSeed;

out vec4 outValues;

void main() {
    Rng rng = rngStart(uvec2(gl_FragCoord.xy), uSampleIndex, uSeed);
    float a = rand1(rng);
    float b = rand1(rng);
    vec2 cd = rand2(rng);
    outValues = vec4(a, b, cd);
}
