// Adaptive sampling, first stage (renderer/passes/adaptive_sampling.h): one texel per 8x8 tile of
// the image, 1 where the tile has converged, else 0. Tiles stop together: the GPU shades pixels in
// groups (llvmpipe 4x4, NVIDIA warps of 8x4), so a lone pixel still sampling costs its whole group,
// and its neighbours may as well take those samples.
// - Default (AdaptiveGoal::Even): every pixel of the tile has converged (adaptive_converged.glsl).
// - GOAL_MEAN: one more sample would lower the tile's relMSE by less than uThreshold^2. With a the
//   tile's relative variance per sample, its relMSE after n samples is a / n, and a sample lowers it
//   by about a / n^2; stopping every tile at the same gain gives each samples in proportion to
//   sqrt(a), the allocation with the least mean relMSE for the samples taken.
#include "adaptive_converged.glsl"

uniform sampler2D uStopDepth; // stopped tiles keep their mean, so they stay converged: not tested again
uniform sampler2D uMeanRadiance;
uniform sampler2D uMeanRadianceSquared;
uniform float uSampleCount;
uniform float uThreshold;
uniform ivec2 uImageSize;

out vec4 outTile;

bool tileConverged(ivec2 origin, ivec2 end) {
#ifdef GOAL_MEAN
    float sum = 0.0;
    for (int y = origin.y; y < end.y; ++y)
        for (int x = origin.x; x < end.x; ++x) {
            ivec2 pixel = ivec2(x, y);
            sum += relativeVariance(texelFetch(uMeanRadiance, pixel, 0).rgb, texelFetch(uMeanRadianceSquared, pixel, 0).rgb, uSampleCount);
        }
    vec2 size = vec2(end - origin);
    float a = sum / (size.x * size.y);
    return a >= 0.0 && sqrt(a) < uThreshold * uSampleCount; // NaN or Inf: not converged
#else
    for (int y = origin.y; y < end.y; ++y)
        for (int x = origin.x; x < end.x; ++x) {
            ivec2 pixel = ivec2(x, y);
            if (!converged(texelFetch(uMeanRadiance, pixel, 0).rgb, texelFetch(uMeanRadianceSquared, pixel, 0).rgb, uSampleCount,
                           uThreshold))
                return false;
        }
    return true;
#endif
}

void main() {
    ivec2 origin = ivec2(gl_FragCoord.xy) * 8;
    if (texelFetch(uStopDepth, origin, 0).r < 1.0) {
        outTile = vec4(1.0);
        return;
    }
    outTile = vec4(tileConverged(origin, min(origin + ivec2(8), uImageSize)) ? 1.0 : 0.0);
}
