// Anti-lag helpers shared by its two stages: this frame's demodulated luminance (the signal SVGF
// accumulates) and the anti-lag history's luminance moments reprojected to a pixel.
// Needs common.glsl and svgf_demodulate.glsl included before it.

uniform sampler2D uRadiance;
uniform sampler2D uDiffuseAlbedo;
uniform sampler2D uSpecularAlbedo;
uniform sampler2D uNormalDepth;
uniform sampler2D uObjectId;
uniform sampler2D uMotion;
uniform sampler2D uPreviousNormalDepth;
uniform sampler2D uPreviousObjectId;
uniform sampler2D uHistory; // x = E[l], y = E[l^2], z = history length in frames
uniform int uHistoryValid;
uniform float uSpikeSigmas; // a sample beyond mean + this many sigmas is clamped (fireflies)

float currentLuminance(ivec2 p) {
    return luminance(demodulate(finiteRadiance(texelFetch(uRadiance, p, 0).rgb), lobeAlbedo(uDiffuseAlbedo, uSpecularAlbedo, p)));
}

// Bilinear over the previous frame's taps that saw this pixel's surface (SVGF's per-tap test, so a
// disoccluded pixel has no history). `weight` < 1e-3: no history.
vec3 reprojectedMoments(ivec2 pixel, out float weight) {
    weight = 0.0;
    vec3 sum = vec3(0.0);
    ivec2 size = textureSize(uHistory, 0);
    vec2 previous = vec2(pixel) + 0.5 + texelFetch(uMotion, pixel, 0).xy;
    if (uHistoryValid == 0 || !insideImage(previous, vec2(size))) return sum;
    vec4 normalDepth = texelFetch(uNormalDepth, pixel, 0);
    float id = texelFetch(uObjectId, pixel, 0).x;
    ivec2 taps[4];
    float weights[4];
    sameSurfaceTaps(previous, size, normalDepth, id, uPreviousNormalDepth, uPreviousObjectId, taps, weights);
    for (int k = 0; k < 4; ++k) {
        if (weights[k] == 0.0) continue;
        sum += weights[k] * texelFetch(uHistory, taps[k], 0).xyz;
        weight += weights[k];
    }
    return weight >= 1.0e-3 ? sum / weight : vec3(0.0);
}

// A rare bright sample is what 1-spp noise is made of, not a change: once a history knows its
// variance (4 frames), samples are clamped to mean + uSpikeSigmas sigma, in the gradient and in the
// moments alike (clamping only one side would make the two means differ on a still image).
float withoutSpike(float l, vec3 history) {
    if (history.z < 4.0) return l;
    float sigma = sqrt(max(history.y - history.x * history.x, 0.0));
    return min(l, history.x + uSpikeSigmas * (sigma + 0.1 * history.x + 1.0e-3));
}
