// SVGF stage 2: where history is short (< 4 frames) the temporal variance means little, so each
// lobe's luminance moments are estimated spatially over a 7x7 edge-aware neighbourhood instead
// (and boosted).
#include "reconstruction/common.glsl"

uniform sampler2D uDiffuse;  // rgb, a = temporal variance
uniform sampler2D uSpecular; // rgb, a = temporal variance
uniform sampler2D uMoments;
uniform sampler2D uHistoryLength; // x
uniform sampler2D uNormalDepth;
uniform sampler2D uObjectId; // filtering never crosses objects (an emitter would bleed onto its surroundings)

out vec4 outDiffuse;
out vec4 outSpecular;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 diffuse = texelFetch(uDiffuse, pixel, 0);
    vec4 specular = texelFetch(uSpecular, pixel, 0);
    float historyLength = texelFetch(uHistoryLength, pixel, 0).x;
    vec4 nd = texelFetch(uNormalDepth, pixel, 0);
    float id = texelFetch(uObjectId, pixel, 0).x;
    outDiffuse = diffuse;
    outSpecular = specular;
    if (historyLength >= 4.0 || nd.w < 0.0) return;
    ivec2 size = textureSize(uDiffuse, 0);
    vec4 m = vec4(0.0); // diffuse E[l], E[l^2], specular E[l], E[l^2]
    float weight = 0.0;
    for (int y = -3; y <= 3; ++y)
        for (int x = -3; x <= 3; ++x) {
            ivec2 q = pixel + ivec2(x, y);
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
            vec4 qnd = texelFetch(uNormalDepth, q, 0);
            if (qnd.w < 0.0 || texelFetch(uObjectId, q, 0).x != id) continue;
            float w = pow(max(dot(nd.xyz, qnd.xyz), 0.0), 128.0) * exp(-abs(nd.w - qnd.w) / (0.05 * nd.w + 1.0e-3));
            vec2 l = vec2(luminance(texelFetch(uDiffuse, q, 0).rgb), luminance(texelFetch(uSpecular, q, 0).rgb));
            m += w * vec4(l.x, l.x * l.x, l.y, l.y * l.y);
            weight += w;
        }
    m /= max(weight, 1.0e-6);
    float boost = 4.0 / max(historyLength, 1.0);
    outDiffuse.a = max(m.y - m.x * m.x, 0.0) * boost;
    outSpecular.a = max(m.w - m.z * m.z, 0.0) * boost;
}
