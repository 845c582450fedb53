// Temporal anti-aliasing and accumulation: the history, reprojected by the motion vectors, is
// clipped towards this frame's 3x3 neighbourhood (variance clipping in YCoCg of perceptual colour,
// Salvi 2016) and blended (see uPerceptualBlend). The blend weight grows with speed (less smear when moving) and is
// 1 where the surface was not visible last frame (id/depth/normal test) or history is invalid.
// History alpha holds its length in frames, so a still view averages up to 1 / uMinBlend frames.
// Anti-lag (stale lighting under the pixel) shortens that length and raises the blend weight.
#include "reconstruction/common.glsl"

uniform sampler2D uCurrent;      // linear radiance
uniform sampler2D uHistory;      // linear radiance, a = history length
uniform sampler2D uMotion;
uniform sampler2D uNormalDepth;
uniform sampler2D uObjectId;
uniform sampler2D uPreviousNormalDepth;
uniform sampler2D uPreviousObjectId;
uniform sampler2D uAntiLag;      // x: how stale history is, 0..1 (anti_lag_pass.h)
uniform int uHistoryValid;
uniform float uMinBlend;         // weight of the current frame on a still, long history
uniform int uClipMode;           // 0: variance clip, 1: clamp to the 3x3 min/max box, 2: none (ghosts)
uniform float uClipGamma;        // box half-size in standard deviations
// 1: blend in the perceptual space too (Karis). It bounds a firefly's weight but darkens 1-spp
// input (Jensen: mean of c/(1+l) < mean of c): -30% energy on the Cornell box, docs/DENOISING.md.
// 0: clip there, blend linear radiance.
uniform int uPerceptualBlend;

out vec4 outColor;

vec3 currentPerceptual(ivec2 p) {
    ivec2 size = textureSize(uCurrent, 0);
    return perceptualFromLinear(finiteRadiance(texelFetch(uCurrent, clamp(p, ivec2(0), size - 1), 0).rgb));
}

// Disocclusion: the surface is new unless some pixel of the previous frame's 3x3 neighbourhood
// around the reprojected position saw it. (A per-tap test would reject the jittered edges that TAA
// exists to anti-alias: their id and depth flip from frame to frame.)
bool seenLastFrame(vec2 position, vec4 normalDepth, float id) {
    ivec2 size = textureSize(uPreviousNormalDepth, 0);
    ivec2 centre = ivec2(floor(position));
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x) {
            ivec2 q = clamp(centre + ivec2(x, y), ivec2(0), size - 1);
            if (sameSurface(normalDepth, id, texelFetch(uPreviousNormalDepth, q, 0), texelFetch(uPreviousObjectId, q, 0).x)) return true;
        }
    return false;
}

// Bilinear history fetch from nearest-filtered storage.
vec4 historyAt(vec2 position) {
    vec2 base = floor(position - 0.5);
    vec2 f = position - 0.5 - base;
    ivec2 size = textureSize(uHistory, 0);
    vec4 sum = vec4(0.0);
    for (int j = 0; j <= 1; ++j)
        for (int i = 0; i <= 1; ++i) {
            ivec2 q = clamp(ivec2(base) + ivec2(i, j), ivec2(0), size - 1);
            sum += (i == 1 ? f.x : 1.0 - f.x) * (j == 1 ? f.y : 1.0 - f.y) * texelFetch(uHistory, q, 0);
        }
    return sum;
}

// Moves `history` towards the box centre until it lies inside the box (clip, not clamp).
vec3 clipToBox(vec3 history, vec3 centre, vec3 extent) {
    vec3 offset = history - centre;
    vec3 units = abs(offset / max(extent, vec3(1.0e-5)));
    float scale = max(units.x, max(units.y, units.z));
    return scale > 1.0 ? centre + offset / scale : history;
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 m1 = vec3(0.0), m2 = vec3(0.0);
    vec3 lowest = vec3(1.0e30), highest = vec3(-1.0e30);
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x) {
            vec3 c = yCoCgFromRgb(currentPerceptual(pixel + ivec2(x, y)));
            m1 += c;
            m2 += c * c;
            lowest = min(lowest, c);
            highest = max(highest, c);
        }
    vec3 mean = m1 / 9.0;
    vec3 sigma = sqrt(max(m2 / 9.0 - mean * mean, vec3(0.0)));
    vec3 current = currentPerceptual(pixel);

    vec2 motion = texelFetch(uMotion, pixel, 0).xy;
    vec2 previous = gl_FragCoord.xy + motion;
    bool found = uHistoryValid != 0 && insideImage(previous, vec2(textureSize(uHistory, 0))) &&
                 seenLastFrame(previous, texelFetch(uNormalDepth, pixel, 0), texelFetch(uObjectId, pixel, 0).x);
    if (!found) {
        outColor = vec4(linearFromPerceptual(current), 1.0);
        return;
    }
    vec4 history = historyAt(previous);
    vec3 past = perceptualFromLinear(finiteRadiance(history.rgb));
    if (uClipMode == 0) past = rgbFromYCoCg(clipToBox(yCoCgFromRgb(past), mean, uClipGamma * sigma));
    else if (uClipMode == 1) past = rgbFromYCoCg(clamp(yCoCgFromRgb(past), lowest, highest));
    // Where anti-lag finds the lighting changed, the history counts as that much shorter.
    float stale = texelFetch(uAntiLag, pixel, 0).x;
    float frames = min(mix(history.a, 0.0, stale) + 1.0, 1.0 / uMinBlend);
    float speed = clamp(length(motion) / 2.0, 0.0, 1.0); // pixels per frame
    float blend = max(mix(1.0 / frames, max(1.0 / frames, 0.5), speed), stale);
    vec3 blended = uPerceptualBlend != 0 ? linearFromPerceptual(mix(past, current, blend))
                                         : mix(linearFromPerceptual(past), linearFromPerceptual(current), blend);
    outColor = vec4(blended, frames);
}
