// SVGF stage 1: temporal accumulation of each lobe's demodulated illumination (diffuse and
// specular apart) and of their first two luminance moments, with a history length per pixel
// (Schied et al. 2017). Disoccluded pixels restart at 1.
// Smooth specular lobes (mirrors, glass, a polished layer) see reflections that move with the
// reflected point's virtual image, not with the surface: their history is fetched at the virtual
// motion (motion.frag.glsl, zw) blended with the surface's by roughness, and where that finds no
// history of this surface, at the surface's. While the reflection moves, their history is kept short
// (reflectionMotion); the diffuse lobe on the same pixel keeps its long history on the surface's
// motion, and a still view keeps both long.
// Guard: NaN/Inf become 0, and a pixel far brighter than all its neighbours (a firefly) is clamped
// to them before it can enter history.
#include "reconstruction/common.glsl"
#include "reconstruction/svgf_demodulate.glsl"

uniform sampler2D uRadiance;
uniform sampler2D uSpecularRadiance;
uniform sampler2D uDiffuseAlbedo;
uniform sampler2D uSpecularAlbedo; // a: roughness
uniform sampler2D uNormalDepth;
uniform sampler2D uObjectId;
uniform sampler2D uMotion;
uniform sampler2D uPreviousNormalDepth;
uniform sampler2D uPreviousObjectId;
uniform sampler2D uHistoryDiffuse;  // filtered illumination, rgb
uniform sampler2D uHistorySpecular;
uniform sampler2D uHistoryMoments;  // diffuse E[l], E[l^2], specular E[l], E[l^2]
uniform sampler2D uHistoryLength;   // x
uniform sampler2D uAntiLag;         // x: how stale history is, 0..1 (anti_lag_pass.h)
uniform int uHistoryValid;
uniform float uAlpha;         // minimum weight of the current frame (0.2 in the paper)
uniform float uMomentsAlpha;
uniform float uFireflyRatio;  // a lobe may exceed its brightest neighbour this many times

out vec4 outDiffuse;  // rgb, a = variance
out vec4 outSpecular; // rgb, a = variance
out vec4 outMoments;
out vec4 outHistoryLength;

// This frame's illumination at p, each lobe demodulated by its albedo.
void illuminationAt(ivec2 p, out vec3 diffuse, out vec3 specular) {
    vec3 d, s;
    splitRadiance(texelFetch(uRadiance, p, 0).rgb, texelFetch(uSpecularRadiance, p, 0).rgb, d, s);
    diffuse = demodulate(d, texelFetch(uDiffuseAlbedo, p, 0).rgb);
    specular = demodulate(s, texelFetch(uSpecularAlbedo, p, 0).rgb);
}

// The whole radiance demodulated by both albedos: what the firefly test compares. (Each lobe alone
// is too sparse for it: a rough specular layer's indirect light comes from the few pixels whose
// first bounce chose that lobe, and clamping those to their neighbours would lose its energy.)
float combinedLuminance(ivec2 p) {
    vec3 radiance = finiteRadiance(texelFetch(uRadiance, p, 0).rgb);
    return luminance(demodulate(radiance, lobeAlbedo(uDiffuseAlbedo, uSpecularAlbedo, p)));
}

// A pixel far brighter than its brightest neighbour is scaled down to the limit, both lobes alike;
// returns its combined luminance after that.
float withoutFireflies(ivec2 pixel, inout vec3 diffuse, inout vec3 specular) {
    ivec2 size = textureSize(uRadiance, 0);
    float brightest = 0.0;
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x)
            if (x != 0 || y != 0) brightest = max(brightest, combinedLuminance(clamp(pixel + ivec2(x, y), ivec2(0), size - 1)));
    float limit = uFireflyRatio * max(brightest, 1.0e-2);
    float l = combinedLuminance(pixel);
    float scale = l > limit ? limit / l : 1.0;
    diffuse *= scale;
    specular *= scale;
    return l * scale;
}

// A restarted history (the chunk's first frame, geometry the camera uncovers) has one sample and no
// moments to judge it by, and its a-trous filter is kept small and strict (svgf_atrous), so a bright
// outlier there stays in the frame at full strength and enters the history at weight 1: at 1 spp the
// rule above does not catch it where the neighbours are noisy too (one of them as bright), and such
// pixels held over half of a first frame's error (docs/DENOISING.md, failure mode 9). There the pixel
// is limited to the mean plus RESTART_SIGMAS standard deviations of its 5x5 neighbours on the same
// object (the filter's own support); thin objects with fewer than RESTART_MIN_NEIGHBOURS keep it.
const float RESTART_SIGMAS = 3.0;
const float RESTART_MIN_NEIGHBOURS = 8.0;
// `l`: the pixel's combined luminance (withoutFireflies).
void withoutOutliersAtRestart(ivec2 pixel, float id, float l, inout vec3 diffuse, inout vec3 specular) {
    ivec2 size = textureSize(uRadiance, 0);
    float sum = 0.0, sumSquares = 0.0, count = 0.0;
    for (int y = -2; y <= 2; ++y)
        for (int x = -2; x <= 2; ++x) {
            ivec2 q = pixel + ivec2(x, y);
            if ((x == 0 && y == 0) || any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
            if (texelFetch(uObjectId, q, 0).x != id) continue;
            float neighbour = combinedLuminance(q);
            sum += neighbour;
            sumSquares += neighbour * neighbour;
            count += 1.0;
        }
    if (count < RESTART_MIN_NEIGHBOURS) return;
    float mean = sum / count;
    float limit = mean + RESTART_SIGMAS * sqrt(max(sumSquares / count - mean * mean, 0.0)) + 1.0e-2;
    float scale = l > limit ? limit / l : 1.0;
    diffuse *= scale;
    specular *= scale;
}

// 1 for a mirror whose reflection moves a quarter pixel a frame or more, 0 from roughness 0.3 up or
// when still: how much shorter the specular lobe's history is (current-frame weight up to
// MOVING_MIRROR_ALPHA). Even reprojected by the reflected image's own motion, a sharp reflection
// loses less to a short history than to a long one: the history is the first a-trous step's output,
// so its blur compounds over the frames it keeps, and a moving view has a new one each frame.
// Measured on a mirror floor under a pan (docs/DENOISING.md, failure mode 4): weight 0.5 -> 0.7
// cut Full's error by 7 %, and 0.2 (no shortening) raised it by 40 %.
const float MOVING_MIRROR_ALPHA = 0.7;
float reflectionMotion(ivec2 p, vec2 motion) {
    float smoothness = 1.0 - clamp(texelFetch(uSpecularAlbedo, p, 0).a / 0.3, 0.0, 1.0);
    return smoothness * clamp(length(motion) / 0.25, 0.0, 1.0);
}

// How far the specular lobe follows the reflected image's virtual motion (motion.frag.glsl) rather
// than the surface's: all of it on a mirror, none from roughness VIRTUAL_ROUGHNESS up, where the
// lobe's wide highlight moves more with the surface than with any one reflected point.
const float VIRTUAL_ROUGHNESS = 0.5;
float virtualMotionWeight(ivec2 p) {
    return 1.0 - clamp(texelFetch(uSpecularAlbedo, p, 0).a / VIRTUAL_ROUGHNESS, 0.0, 1.0);
}

// Bilinear history around `previous` over the taps that saw the same surface: rgb from `history`,
// moments (two channels from `firstMoment`), length; w: the taps' total weight (0: none).
struct Reprojected {
    vec3 history;
    vec2 moments;
    float frames;
    float weight;
};

Reprojected reproject(vec2 previous, sampler2D history, int firstMoment, vec4 normalDepth, float id) {
    Reprojected r = Reprojected(vec3(0.0), vec2(0.0), 0.0, 0.0);
    if (uHistoryValid == 0 || !insideImage(previous, vec2(textureSize(uRadiance, 0)))) return r;
    ivec2 taps[4];
    float weights[4];
    sameSurfaceTaps(previous, textureSize(uRadiance, 0), normalDepth, id, uPreviousNormalDepth, uPreviousObjectId, taps, weights);
    for (int k = 0; k < 4; ++k) {
        if (weights[k] == 0.0) continue;
        float w = weights[k];
        ivec2 q = taps[k];
        vec4 moments = texelFetch(uHistoryMoments, q, 0);
        r.history += w * finiteRadiance(texelFetch(history, q, 0).rgb);
        r.moments += w * (firstMoment == 0 ? moments.xy : moments.zw);
        r.frames += w * texelFetch(uHistoryLength, q, 0).x;
        r.weight += w;
    }
    if (r.weight < 1.0e-3) return Reprojected(vec3(0.0), vec2(0.0), 0.0, 0.0);
    r.history /= r.weight;
    r.moments /= r.weight;
    r.frames /= r.weight;
    return r;
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 diffuse, specular;
    illuminationAt(pixel, diffuse, specular);
    float combined = withoutFireflies(pixel, diffuse, specular);
    vec4 l = vec4(luminance(diffuse), 0.0, luminance(specular), 0.0);
    l.yw = l.xz * l.xz;
    vec4 normalDepth = texelFetch(uNormalDepth, pixel, 0);
    float id = texelFetch(uObjectId, pixel, 0).x;
    vec4 motion = texelFetch(uMotion, pixel, 0);

    // The diffuse lobe follows the surface; the specular lobe the reflected image as far as its
    // roughness says, or the surface where that finds no history of this surface (a curved mirror's
    // image is approximate, and may reproject off it).
    Reprojected d = reproject(gl_FragCoord.xy + motion.xy, uHistoryDiffuse, 0, normalDepth, id);
    if (d.weight == 0.0) {
        withoutOutliersAtRestart(pixel, id, combined, diffuse, specular);
        l = vec4(luminance(diffuse), 0.0, luminance(specular), 0.0);
        l.yw = l.xz * l.xz;
        outDiffuse = vec4(diffuse, 0.0);
        outSpecular = vec4(specular, 0.0);
        outMoments = l;
        outHistoryLength = vec4(1.0, 0.0, 0.0, 0.0);
        return;
    }
    vec2 specularMotion = mix(motion.xy, motion.zw, virtualMotionWeight(pixel));
    Reprojected s = reproject(gl_FragCoord.xy + specularMotion, uHistorySpecular, 1, normalDepth, id);
    if (s.weight == 0.0) {
        s = reproject(gl_FragCoord.xy + motion.xy, uHistorySpecular, 1, normalDepth, id);
        specularMotion = motion.xy;
    }
    // Where the lighting changed, history is shortened (and the variance turns spatial) by anti-lag.
    float stale = texelFetch(uAntiLag, pixel, 0).x;
    float historyLength = mix(d.frames, 0.0, stale) + 1.0;
    float alpha = max(max(uAlpha, 1.0 / historyLength), stale);
    float momentsAlpha = max(max(uMomentsAlpha, 1.0 / historyLength), stale);
    float specularShort = mix(uAlpha, MOVING_MIRROR_ALPHA, reflectionMotion(pixel, specularMotion));
    float specularAlpha = max(alpha, specularShort);
    float specularMomentsAlpha = max(momentsAlpha, specularShort);
    vec4 m = vec4(mix(d.moments, l.xy, momentsAlpha), mix(s.moments, l.zw, specularMomentsAlpha));
    outDiffuse = vec4(mix(d.history, diffuse, alpha), max(m.y - m.x * m.x, 0.0));
    outSpecular = vec4(mix(s.history, specular, specularAlpha), max(m.w - m.z * m.z, 0.0));
    outMoments = m;
    outHistoryLength = vec4(historyLength, 0.0, 0.0, 0.0);
}
