// SVGF stage 1: temporal accumulation of demodulated illumination and of its first two luminance
// moments, with a history length per pixel (Schied et al. 2017). Disoccluded pixels restart at 1.
// Smooth specular surfaces (mirrors, glass) see reflections whose motion the primary motion vectors
// do not describe: their history is kept short (current-frame weight up to 0.5 at roughness 0).
// Guard: NaN/Inf become 0, and a pixel far brighter than all its neighbours (a firefly) is clamped
// to them before it can enter history.
#include "reconstruction/common.glsl"
#include "reconstruction/svgf_demodulate.glsl"

uniform sampler2D uRadiance;
uniform sampler2D uDiffuseAlbedo;
uniform sampler2D uSpecularAlbedo; // a: roughness
uniform sampler2D uNormalDepth;
uniform sampler2D uObjectId;
uniform sampler2D uMotion;
uniform sampler2D uPreviousNormalDepth;
uniform sampler2D uPreviousObjectId;
uniform sampler2D uHistoryIllumination; // rgb
uniform sampler2D uHistoryMoments;      // x = E[l], y = E[l^2], z = history length
uniform int uHistoryValid;
uniform float uAlpha;         // minimum weight of the current frame (0.2 in the paper)
uniform float uMomentsAlpha;
uniform float uFireflyRatio;  // a pixel may exceed its brightest neighbour this many times

out vec4 outIllumination; // rgb, a = variance
out vec4 outMoments;

vec3 illuminationAt(ivec2 p) {
    return demodulate(finiteRadiance(texelFetch(uRadiance, p, 0).rgb), lobeAlbedo(uDiffuseAlbedo, uSpecularAlbedo, p));
}

vec3 withoutFirefly(ivec2 pixel, vec3 c) {
    ivec2 size = textureSize(uRadiance, 0);
    float brightest = 0.0;
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x)
            if (x != 0 || y != 0) brightest = max(brightest, luminance(illuminationAt(clamp(pixel + ivec2(x, y), ivec2(0), size - 1))));
    float limit = uFireflyRatio * max(brightest, 1.0e-2);
    float l = luminance(c);
    return l > limit ? c * (limit / l) : c;
}

// 1 for a smooth surface whose light is mostly specular, 0 for rough or diffuse ones.
float mirrorLikeness(ivec2 p) {
    vec4 specular = texelFetch(uSpecularAlbedo, p, 0);
    float s = luminance(specular.rgb), d = luminance(texelFetch(uDiffuseAlbedo, p, 0).rgb);
    return s / max(s + d, 1.0e-4) * (1.0 - clamp(specular.a / 0.3, 0.0, 1.0));
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 current = withoutFirefly(pixel, illuminationAt(pixel));
    float l = luminance(current);
    vec4 normalDepth = texelFetch(uNormalDepth, pixel, 0);
    float id = texelFetch(uObjectId, pixel, 0).x;
    vec2 previous = gl_FragCoord.xy + texelFetch(uMotion, pixel, 0).xy;

    // Bilinear reprojection over the taps that saw the same surface.
    vec3 illumination = vec3(0.0);
    vec3 moments = vec3(0.0);
    float weight = 0.0;
    if (uHistoryValid != 0 && insideImage(previous, vec2(textureSize(uRadiance, 0)))) {
        vec2 base = floor(previous - 0.5);
        vec2 f = previous - 0.5 - base;
        ivec2 size = textureSize(uRadiance, 0);
        for (int j = 0; j <= 1; ++j)
            for (int i = 0; i <= 1; ++i) {
                ivec2 q = ivec2(base) + ivec2(i, j);
                if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
                if (!sameSurface(normalDepth, id, texelFetch(uPreviousNormalDepth, q, 0), texelFetch(uPreviousObjectId, q, 0).x)) continue;
                float w = (i == 1 ? f.x : 1.0 - f.x) * (j == 1 ? f.y : 1.0 - f.y);
                illumination += w * finiteRadiance(texelFetch(uHistoryIllumination, q, 0).rgb);
                moments += w * texelFetch(uHistoryMoments, q, 0).xyz;
                weight += w;
            }
    }
    if (weight < 1.0e-3) {
        outIllumination = vec4(current, 0.0);
        outMoments = vec4(l, l * l, 1.0, 0.0);
        return;
    }
    illumination /= weight;
    moments /= weight;
    float historyLength = moments.z + 1.0;
    float alpha = max(max(uAlpha, 1.0 / historyLength), mix(uAlpha, 0.5, mirrorLikeness(pixel)));
    float momentsAlpha = max(uMomentsAlpha, 1.0 / historyLength);
    vec2 m = mix(moments.xy, vec2(l, l * l), momentsAlpha);
    outIllumination = vec4(mix(illumination, current, alpha), max(m.y - m.x * m.x, 0.0));
    outMoments = vec4(m, historyLength, 0.0);
}
