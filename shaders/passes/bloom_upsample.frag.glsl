// Bloom, up: this level's own blur plus the coarser levels' sum, read bilinearly at this size.
#include "bloom_sample.glsl"

uniform sampler2D uCoarser; // the sum of the levels below, half this size
uniform sampler2D uLevel;   // this level

out vec4 outColor;

void main() {
    vec2 position = gl_FragCoord.xy;
    outColor = texelFetch(uLevel, ivec2(position), 0) + bilinear(uCoarser, 0.5 * position);
}
