// Anti-lag, stage 1, one fragment per stratum of uStratum x uStratum pixels: a temporal gradient
// for a fragment pipeline. A-SVGF (Schied et al. 2018) re-shades last frame's samples with their
// random numbers to get a noise-free difference; here the stratum's mean of this frame's noisy
// demodulated luminance is compared with the mean of its reprojected history, and the difference is
// trusted only where it exceeds what the history's temporal moments say 1-spp noise can do.
// Output x = lambda in [0, 1] (0: history still right, 1: history stale), y = the difference in
// standard deviations, z = relative change, w = pixels that had history.
#include "reconstruction/common.glsl"
#include "reconstruction/svgf_demodulate.glsl"
#include "reconstruction/anti_lag_reproject.glsl"

uniform int uStratum;
uniform float uNoiseLow;   // below this many standard deviations a change is noise
uniform float uNoiseHigh;  // above it, a change is certain
uniform float uFullChange; // relative change of the mean that discards history entirely
uniform float uSpikeSigmas; // a sample beyond mean + this many sigmas is clamped (fireflies)

out vec4 outGradient;

void main() {
    ivec2 size = textureSize(uRadiance, 0);
    ivec2 origin = ivec2(gl_FragCoord.xy) * uStratum;
    float count = 0.0, sumL = 0.0, sumL2 = 0.0, sumHistory = 0.0;
    float longVariance = 0.0; // sum over long histories of Var(sample) (1 + 1/n)
    float shortWeight = 0.0;  // sum of (1 + 1/n) for histories too short for their moments
    for (int y = 0; y < uStratum; ++y)
        for (int x = 0; x < uStratum; ++x) {
            ivec2 p = origin + ivec2(x, y);
            if (any(greaterThanEqual(p, size))) continue;
            float weight;
            vec3 h = reprojectedMoments(p, weight);
            if (weight < 1.0e-3) continue;
            float l = currentLuminance(p);
            float n = max(h.z, 1.0);
            if (n >= 4.0) {
                float variance = max(h.y - h.x * h.x, 0.0);
                // A rare bright sample is what the noise is made of at 1 spp, not a change.
                l = min(l, h.x + uSpikeSigmas * (sqrt(variance) + 0.1 * h.x + 1.0e-3));
                longVariance += variance * (1.0 + 1.0 / n);
            } else {
                shortWeight += 1.0 + 1.0 / n;
            }
            count += 1.0;
            sumL += l;
            sumL2 += l * l;
            sumHistory += h.x;
        }
    if (count < 2.0) {
        outGradient = vec4(0.0, 0.0, 0.0, count);
        return;
    }
    float mean = sumL / count;
    float historyMean = sumHistory / count;
    // Short histories know no temporal variance: the stratum's spatial variance stands in for it.
    float spatial = max(sumL2 / count - mean * mean, 0.0) * count / (count - 1.0);
    float variance = (longVariance + shortWeight * spatial) / (count * count);
    float delta = abs(mean - historyMean);
    float sigmas = delta / sqrt(variance + 1.0e-10);
    float relative = delta / max(max(mean, historyMean), 1.0e-2);
    float lambda = smoothstep(uNoiseLow, uNoiseHigh, sigmas) * min(relative / uFullChange, 1.0);
    outGradient = vec4(lambda, sigmas, relative, count);
}
