// Anti-lag, stage 1, one fragment per stratum of uStratum x uStratum pixels: a temporal gradient
// for a fragment pipeline. A-SVGF (Schied et al. 2018) re-shades last frame's samples with their
// random numbers to get a noise-free difference; here the stratum's mean of this frame's noisy
// demodulated luminance is compared with the mean of its reprojected history, and the difference is
// trusted only where it stands out of the spread of the per-pixel differences (a t-test).
// Output x = lambda in [0, 1] (0: history still right, 1: history stale), y = the difference in
// standard deviations, z = relative change, w = pixels that had history.
#include "reconstruction/common.glsl"
#include "reconstruction/svgf_demodulate.glsl"
#include "reconstruction/anti_lag_reproject.glsl"

uniform int uStratum;
uniform float uNoiseLow;   // below this many standard deviations a change is noise
uniform float uNoiseHigh;  // above it, a change is certain
uniform float uFullChange; // relative change of the mean that discards history entirely
uniform float uMinPixels;  // fewer pixels with history than this: no gradient

out vec4 outGradient;

void main() {
    ivec2 size = textureSize(uRadiance, 0);
    ivec2 origin = ivec2(gl_FragCoord.xy) * uStratum;
    float count = 0.0, sumD = 0.0, sumD2 = 0.0, sumL = 0.0, sumHistory = 0.0;
    for (int y = 0; y < uStratum; ++y)
        for (int x = 0; x < uStratum; ++x) {
            ivec2 p = origin + ivec2(x, y);
            if (any(greaterThanEqual(p, size))) continue;
            float weight;
            vec3 h = reprojectedMoments(p, weight);
            if (weight < 1.0e-3) continue;
            float l = withoutSpike(currentLuminance(p), h);
            float d = l - h.x; // each pixel against its own history: lighting that varies across the stratum cancels
            count += 1.0;
            sumD += d;
            sumD2 += d * d;
            sumL += l;
            sumHistory += h.x;
        }
    if (count < uMinPixels) { // strata cut by silhouettes are too few samples to tell
        outGradient = vec4(0.0, 0.0, 0.0, count);
        return;
    }
    // A paired t-test: the mean difference over its standard error, estimated from the spread of the
    // differences in this very stratum, so heavy-tailed 1-spp noise (one bright sample moves the
    // mean and the spread alike) does not pass for a change, while a change that moves every pixel
    // does, however quiet the pixels were before.
    float meanD = sumD / count;
    float varianceD = max(sumD2 / count - meanD * meanD, 0.0) * count / (count - 1.0);
    float sigmas = abs(meanD) / sqrt(varianceD / count + 1.0e-10);
    float relative = abs(meanD) / max(max(sumL, sumHistory) / count, 1.0e-2);
    float lambda = smoothstep(uNoiseLow, uNoiseHigh, sigmas) * min(relative / uFullChange, 1.0);
    outGradient = vec4(lambda, sigmas, relative, count);
}
