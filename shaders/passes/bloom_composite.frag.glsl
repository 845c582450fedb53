// Bloom, last: the image and the mean of its blurs (levels 1..N), mixed by strength s:
// (1 - s) x + s blur. Every blur keeps the mean, so the mix moves light without adding any.
#include "bloom_sample.glsl"

uniform sampler2D uImage;
uniform sampler2D uLevels; // the sum of levels 1..N, half this size
uniform float uLevelCount;
uniform float uStrength;

out vec4 outColor;

void main() {
    vec2 position = gl_FragCoord.xy;
    vec4 image = texelFetch(uImage, ivec2(position), 0);
    vec3 blur = bilinear(uLevels, 0.5 * position).rgb / uLevelCount;
    outColor = vec4(mix(image.rgb, blur, uStrength), image.a);
}
