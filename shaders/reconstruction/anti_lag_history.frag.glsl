// Anti-lag, stage 2, per pixel: lambda from the strata (anti_lag_gradient.frag.glsl) taken as the
// largest of the four nearest, so a stale stratum covers its own pixels fully; and the anti-lag
// history of luminance moments, shortened by lambda so that after a change it follows the new
// signal at once and stops reporting it.
// Outputs: moments (x = E[l], y = E[l^2], z = history length), anti-lag (x = lambda).
#include "reconstruction/common.glsl"
#include "reconstruction/svgf_demodulate.glsl"
#include "reconstruction/anti_lag_reproject.glsl"

uniform sampler2D uGradient; // per stratum, x = lambda
uniform int uStratum;
uniform float uAlpha;        // minimum weight of the current frame in the moments

out vec4 outMoments;
out vec4 outAntiLag;

float lambdaAt(ivec2 pixel) {
    ivec2 size = textureSize(uGradient, 0);
    vec2 coarse = (vec2(pixel) + 0.5) / float(uStratum) - 0.5;
    ivec2 base = ivec2(floor(coarse));
    float lambda = 0.0;
    for (int j = 0; j <= 1; ++j)
        for (int i = 0; i <= 1; ++i)
            lambda = max(lambda, texelFetch(uGradient, clamp(base + ivec2(i, j), ivec2(0), size - 1), 0).x);
    return lambda;
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float lambda = lambdaAt(pixel);
    float weight;
    vec3 h = reprojectedMoments(pixel, weight);
    float l = weight < 1.0e-3 ? currentLuminance(pixel) : withoutSpike(currentLuminance(pixel), h);
    outAntiLag = vec4(lambda, 0.0, 0.0, 0.0);
    if (weight < 1.0e-3) {
        outMoments = vec4(l, l * l, 1.0, 0.0);
        return;
    }
    float frames = 1.0 + h.z * (1.0 - lambda);
    float alpha = max(uAlpha, 1.0 / frames);
    outMoments = vec4(mix(h.xy, vec2(l, l * l), alpha), frames, 0.0);
}
