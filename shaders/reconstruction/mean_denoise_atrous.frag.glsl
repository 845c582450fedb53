// Mean denoiser, stage 2 (run N times with step 2^i): an edge-aware a-trous wavelet step over the
// demodulated mean (rgb) and the variance of that mean (a). Weights: B3-spline kernel x depth x
// normal x luminance, never across objects; the luminance stop scales with the standard deviation
// of the mean, which falls as 1/sqrt(n): the more samples, the less the filter moves a pixel, down
// to the mean itself.
#include "reconstruction/common.glsl"

uniform sampler2D uIllumination; // rgb, a = variance of the mean
uniform sampler2D uNormalDepth;
uniform sampler2D uObjectId;
uniform int uStep;
uniform float uSigmaLuminance;
uniform float uSigmaNormal;
uniform float uSigmaDepth;

out vec4 outIllumination;

float blurredVariance(ivec2 pixel, ivec2 size) {
    const float kernel[2] = float[2](0.25, 0.125);
    float sum = 0.0;
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x) {
            ivec2 q = clamp(pixel + ivec2(x, y), ivec2(0), size - 1);
            sum += kernel[abs(x)] * kernel[abs(y)] * texelFetch(uIllumination, q, 0).a;
        }
    return sum * 4.0; // the 3x3 weights sum to 1/4
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(uIllumination, 0);
    vec4 centre = texelFetch(uIllumination, pixel, 0);
    vec4 nd = texelFetch(uNormalDepth, pixel, 0);
    outIllumination = centre;
    if (nd.w < 0.0) return;
    float id = texelFetch(uObjectId, pixel, 0).x;
    float lCentre = luminance(centre.rgb);
    float lScale = uSigmaLuminance * sqrt(max(min(centre.a, blurredVariance(pixel, size)), 0.0)) + 1.0e-8;

    const float kernel[3] = float[3](3.0 / 8.0, 1.0 / 4.0, 1.0 / 16.0);
    float w0 = kernel[0] * kernel[0];
    vec4 sum = vec4(centre.rgb * w0, centre.a * w0 * w0);
    float weight = w0;
    for (int y = -2; y <= 2; ++y)
        for (int x = -2; x <= 2; ++x) {
            if (x == 0 && y == 0) continue;
            ivec2 q = pixel + ivec2(x, y) * uStep;
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
            vec4 qnd = texelFetch(uNormalDepth, q, 0);
            if (qnd.w < 0.0 || texelFetch(uObjectId, q, 0).x != id) continue;
            vec4 c = texelFetch(uIllumination, q, 0);
            float wz = abs(nd.w - qnd.w) / (uSigmaDepth * 0.02 * nd.w * float(uStep) * length(vec2(x, y)) + 1.0e-4);
            float wn = pow(max(dot(nd.xyz, qnd.xyz), 0.0), uSigmaNormal);
            float wl = abs(luminance(c.rgb) - lCentre) / lScale;
            float w = kernel[abs(x)] * kernel[abs(y)] * wn * exp(-wz - wl);
            sum += vec4(c.rgb * w, c.a * w * w);
            weight += w;
        }
    outIllumination = vec4(sum.rgb / weight, sum.a / (weight * weight));
}
