// Mean denoiser, stage 1: the accumulated mean demodulated by its surface's albedo (both lobes: the
// still mean keeps them together), and in alpha the variance of that mean's luminance. With enough
// samples it is the per-pixel sample variance over n; with fewer (the first frames) the per-pixel
// estimate means little, so the spatial variance of the mean image over a 5x5 edge-aware
// neighbourhood is taken where it is larger. Misses (the environment) are left as they are.
#include "reconstruction/svgf_demodulate.glsl"

uniform sampler2D uRadiance;
uniform sampler2D uRadianceSquared;
uniform sampler2D uDiffuseAlbedo;
uniform sampler2D uSpecularAlbedo;
uniform sampler2D uNormalDepth;
uniform sampler2D uObjectId;
uniform float uSamples; // n

// The spatial estimate's share falls from whole at 1 sample to none at TRUSTED_SAMPLES: a sudden
// switch made the filter's reach drop at once, and the image worse from 2 to 4 samples.
const float TRUSTED_SAMPLES = 5.0;

out vec4 outIllumination;

vec3 albedoAt(ivec2 p) { return texelFetch(uDiffuseAlbedo, p, 0).rgb + texelFetch(uSpecularAlbedo, p, 0).rgb; }

vec3 illuminationAt(ivec2 p) { return demodulate(finiteRadiance(texelFetch(uRadiance, p, 0).rgb), albedoAt(p)); }

// Variance of the mean's luminance from the samples themselves: the channels of a path's radiance
// move together, so the luminance's deviation is the weighted sum of the channels' deviations.
float sampleVarianceOfMean(ivec2 pixel, vec3 mean, vec3 albedo) {
    if (uSamples < 2.0) return 0.0;
    vec3 m2 = texelFetch(uRadianceSquared, pixel, 0).rgb;
    vec3 variance = max(m2 - mean * mean, vec3(0.0)) * (uSamples / (uSamples - 1.0));
    vec3 scale = mix(vec3(1.0), 1.0 / max(albedo, vec3(MIN_ALBEDO)), greaterThan(albedo, vec3(MIN_ALBEDO)));
    float deviation = luminance(sqrt(variance) * scale);
    return deviation * deviation / uSamples;
}

// The mean image's own spatial variance of luminance around `pixel`, on the same surface.
float spatialVariance(ivec2 pixel, vec4 nd, float id) {
    ivec2 size = textureSize(uRadiance, 0);
    vec2 m = vec2(0.0);
    float weight = 0.0;
    for (int y = -2; y <= 2; ++y)
        for (int x = -2; x <= 2; ++x) {
            ivec2 q = pixel + ivec2(x, y);
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
            vec4 qnd = texelFetch(uNormalDepth, q, 0);
            if (qnd.w < 0.0 || texelFetch(uObjectId, q, 0).x != id) continue;
            float w = pow(max(dot(nd.xyz, qnd.xyz), 0.0), 128.0) * exp(-abs(nd.w - qnd.w) / (0.05 * nd.w + 1.0e-3));
            float l = luminance(illuminationAt(q));
            m += w * vec2(l, l * l);
            weight += w;
        }
    m /= max(weight, 1.0e-6);
    return max(m.y - m.x * m.x, 0.0);
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 mean = finiteRadiance(texelFetch(uRadiance, pixel, 0).rgb);
    vec4 nd = texelFetch(uNormalDepth, pixel, 0);
    if (nd.w < 0.0) {
        outIllumination = vec4(mean, 0.0);
        return;
    }
    vec3 albedo = albedoAt(pixel);
    float variance = sampleVarianceOfMean(pixel, mean, albedo);
    float spatialShare = clamp((TRUSTED_SAMPLES - uSamples) / (TRUSTED_SAMPLES - 1.0), 0.0, 1.0);
    if (spatialShare > 0.0)
        variance = max(variance, spatialShare * spatialVariance(pixel, nd, texelFetch(uObjectId, pixel, 0).x));
    outIllumination = vec4(demodulate(mean, albedo), variance);
}
