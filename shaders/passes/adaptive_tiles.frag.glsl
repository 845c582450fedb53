// Adaptive sampling, first stage (renderer/passes/adaptive_sampling.h): one texel per 8x8 tile of
// the image, 1 where every pixel of the tile has converged, else 0. Tiles stop together: the GPU
// shades pixels in groups (llvmpipe 4x4, NVIDIA warps of 8x4), so a lone pixel still sampling
// costs its whole group, and its neighbours may as well take those samples.
#include "adaptive_converged.glsl"

uniform sampler2D uStopDepth; // stopped tiles keep their mean, so they stay converged: not tested again
uniform sampler2D uMeanRadiance;
uniform sampler2D uMeanRadianceSquared;
uniform float uSampleCount;
uniform float uThreshold;
uniform ivec2 uImageSize;

out vec4 outTile;

void main() {
    ivec2 origin = ivec2(gl_FragCoord.xy) * 8;
    if (texelFetch(uStopDepth, origin, 0).r < 1.0) {
        outTile = vec4(1.0);
        return;
    }
    ivec2 end = min(origin + ivec2(8), uImageSize);
    for (int y = origin.y; y < end.y; ++y)
        for (int x = origin.x; x < end.x; ++x) {
            ivec2 pixel = ivec2(x, y);
            if (!converged(texelFetch(uMeanRadiance, pixel, 0).rgb, texelFetch(uMeanRadianceSquared, pixel, 0).rgb, uSampleCount,
                           uThreshold)) {
                outTile = vec4(0.0);
                return;
            }
        }
    outTile = vec4(1.0);
}
