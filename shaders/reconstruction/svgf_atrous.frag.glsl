// SVGF stage 3 (run N times with step 2^i): an edge-aware a-trous wavelet step over each lobe's
// illumination (rgb) and variance (a). Weights: B3-spline kernel x depth x normal x luminance, the
// luminance scale set by the lobe's 3x3-blurred variance. Misses (the environment) pass through.
// The specular lobe follows the surface's roughness r (specular albedo's a): smooth lobes get
// fewer iterations (1 at r = 0, all from uSpecularFullRoughness up: a small kernel keeps a sharp
// reflection sharp), up to 2x stricter luminance and 4x stricter normal stops, and neighbours of a
// different roughness count less.
// A pixel whose history restarted (disocclusion: the band a moving object leaves, the edge a pan
// reveals; every pixel in the first frames) gets a 4x stricter luminance stop until its history is
// 8 frames long, and a smaller kernel (steps up to 2^n px) while it is under 4. Its variance is the
// spatial 7x7 estimate, which measures the light's spatial change (a contact shadow beside lit
// ground) as much as noise, so the full filter blurred that change away, and the blur of the first
// frames stayed in the filtered history. Where anti-lag shortened the history (the light changed,
// the surface did not) the neighbours are as noisy as the pixel, and the full filter stays.
// docs/DENOISING.md, failure modes 1 and 3.
#include "reconstruction/common.glsl"

uniform sampler2D uDiffuse;  // rgb, a = variance
uniform sampler2D uSpecular; // rgb, a = variance
uniform sampler2D uNormalDepth;
uniform sampler2D uObjectId; // filtering never crosses objects (an emitter would bleed onto its surroundings)
uniform sampler2D uSpecularAlbedo; // a: roughness
uniform sampler2D uHistoryLength;  // x: frames, 1 after a restart (svgf_reproject)
uniform sampler2D uAntiLag;        // x: how much of that shortness anti-lag caused, 0..1
uniform int uStep;
uniform int uIteration;        // 0-based
uniform int uIterations;
uniform int uHistoryValid;     // 0: no pixel has history (a chunk's first frame, after a cut)
uniform float uSigmaLuminance; // 4 in the paper
uniform float uSigmaNormal;    // 128
uniform float uSigmaDepth;     // 1
uniform float uSpecularFullRoughness;

const float SMALL_KERNEL_HISTORY = 4.0;   // frames: steps up to 2^n px below it
const float STRICT_STOP_HISTORY = 8.0;    // frames: the stricter luminance stop below it
const float RESTARTED_LUMINANCE_STOP = 0.25; // uSigmaLuminance's scale there
// In a frame where no pixel has history (a chunk's first frame, after a cut or a resize) only 2x:
// the 4x stop protects a band of restarted pixels from spreading the spatial variance's shading
// change into the history their long-history neighbours average, and here every pixel is such a
// pixel, so it left the first frame mostly unfiltered. Measured on a sunlit room panned fast
// (docs/DENOISING.md, failure mode 9): first frame 0.42x -> 0.36x raw with the frames after it
// unchanged; no stop (1) gives the same first frame but more error after; the full kernel 0.70x.
const float FIRST_FRAME_LUMINANCE_STOP = 0.5;

out vec4 outDiffuse;
out vec4 outSpecular;

vec2 blurredVariance(ivec2 pixel, ivec2 size) {
    const float kernel[2] = float[2](0.25, 0.125);
    vec2 sum = vec2(0.0);
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x) {
            ivec2 q = clamp(pixel + ivec2(x, y), ivec2(0), size - 1);
            sum += kernel[abs(x)] * kernel[abs(y)] * vec2(texelFetch(uDiffuse, q, 0).a, texelFetch(uSpecular, q, 0).a);
        }
    return sum * 4.0; // the 3x3 weights sum to 1/4
}

// One lobe's running sum: rgb weighted by w, variance by w^2.
struct Sum {
    vec4 value;
    float weight;
};

void addTap(inout Sum s, vec4 c, float w) {
    s.value += vec4(c.rgb * w, c.a * w * w);
    s.weight += w;
}

vec4 result(Sum s) { return vec4(s.value.rgb / s.weight, s.value.a / (s.weight * s.weight)); }

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(uDiffuse, 0);
    vec4 diffuse = texelFetch(uDiffuse, pixel, 0);
    vec4 specular = texelFetch(uSpecular, pixel, 0);
    vec4 nd = texelFetch(uNormalDepth, pixel, 0);
    float id = texelFetch(uObjectId, pixel, 0).x;
    outDiffuse = diffuse;
    outSpecular = specular;
    if (nd.w < 0.0) return;
    // The history's length as far as it is short for want of a surface, not of stable light.
    float stale = texelFetch(uAntiLag, pixel, 0).x;
    float restarted = mix(texelFetch(uHistoryLength, pixel, 0).x, STRICT_STOP_HISTORY, stale);
    if (restarted < SMALL_KERNEL_HISTORY && float(uStep) > exp2(restarted)) return;
    float strict = uHistoryValid == 0 ? FIRST_FRAME_LUMINANCE_STOP : RESTARTED_LUMINANCE_STOP;
    float sigmaLuminance = uSigmaLuminance * (restarted < STRICT_STOP_HISTORY ? mix(strict, 1.0, stale) : 1.0);
    float roughness = texelFetch(uSpecularAlbedo, pixel, 0).a;
    float rough = clamp(roughness / max(uSpecularFullRoughness, 1.0e-3), 0.0, 1.0);
    bool filterSpecular = uIteration < 1 + int(floor(float(uIterations - 1) * rough + 0.5));

    const float kernel[3] = float[3](3.0 / 8.0, 1.0 / 4.0, 1.0 / 16.0);
    vec2 lCentre = vec2(luminance(diffuse.rgb), luminance(specular.rgb));
    vec2 lScale = sigmaLuminance * vec2(1.0, mix(0.5, 1.0, rough)) * sqrt(max(blurredVariance(pixel, size), vec2(0.0))) + 1.0e-6;
    vec2 normalExponent = uSigmaNormal * vec2(1.0, mix(4.0, 1.0, rough));
    float centre = kernel[0] * kernel[0];
    Sum d = Sum(diffuse * vec4(vec3(centre), centre * centre), centre);
    Sum s = Sum(specular * vec4(vec3(centre), centre * centre), centre);
    for (int y = -2; y <= 2; ++y)
        for (int x = -2; x <= 2; ++x) {
            if (x == 0 && y == 0) continue;
            ivec2 q = pixel + ivec2(x, y) * uStep;
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
            vec4 qnd = texelFetch(uNormalDepth, q, 0);
            if (qnd.w < 0.0 || texelFetch(uObjectId, q, 0).x != id) continue;
            float wz = abs(nd.w - qnd.w) / (uSigmaDepth * 0.02 * nd.w * float(uStep) * length(vec2(x, y)) + 1.0e-4);
            float cosNormals = max(dot(nd.xyz, qnd.xyz), 0.0);
            float base = kernel[abs(x)] * kernel[abs(y)] * exp(-wz);
            vec4 qd = texelFetch(uDiffuse, q, 0);
            addTap(d, qd, base * pow(cosNormals, normalExponent.x) * exp(-abs(luminance(qd.rgb) - lCentre.x) / lScale.x));
            if (!filterSpecular) continue;
            vec4 qs = texelFetch(uSpecular, q, 0);
            float wr = exp(-abs(texelFetch(uSpecularAlbedo, q, 0).a - roughness) * 10.0);
            addTap(s, qs, base * wr * pow(cosNormals, normalExponent.y) * exp(-abs(luminance(qs.rgb) - lCentre.y) / lScale.y));
        }
    outDiffuse = result(d);
    outSpecular = filterSpecular ? result(s) : specular;
}
