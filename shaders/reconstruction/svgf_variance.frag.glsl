// SVGF stage 2: where history is short (< 4 frames) the temporal variance means little, so the
// moments are estimated spatially over a 7x7 edge-aware neighbourhood instead (and boosted).
#include "reconstruction/common.glsl"

uniform sampler2D uIllumination; // rgb, a = temporal variance
uniform sampler2D uMoments;
uniform sampler2D uNormalDepth;
uniform sampler2D uObjectId; // filtering never crosses objects (an emitter would bleed onto its surroundings)

out vec4 outIllumination;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 centre = texelFetch(uIllumination, pixel, 0);
    float historyLength = texelFetch(uMoments, pixel, 0).z;
    vec4 nd = texelFetch(uNormalDepth, pixel, 0);
    float id = texelFetch(uObjectId, pixel, 0).x;
    if (historyLength >= 4.0 || nd.w < 0.0) {
        outIllumination = centre;
        return;
    }
    ivec2 size = textureSize(uIllumination, 0);
    vec3 sum = vec3(0.0);
    vec2 m = vec2(0.0);
    float weight = 0.0;
    for (int y = -3; y <= 3; ++y)
        for (int x = -3; x <= 3; ++x) {
            ivec2 q = pixel + ivec2(x, y);
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
            vec4 qnd = texelFetch(uNormalDepth, q, 0);
            if (qnd.w < 0.0 || texelFetch(uObjectId, q, 0).x != id) continue;
            float w = pow(max(dot(nd.xyz, qnd.xyz), 0.0), 128.0) * exp(-abs(nd.w - qnd.w) / (0.05 * nd.w + 1.0e-3));
            vec3 c = texelFetch(uIllumination, q, 0).rgb;
            float l = luminance(c);
            sum += w * c;
            m += w * vec2(l, l * l);
            weight += w;
        }
    m /= max(weight, 1.0e-6);
    float variance = max(m.y - m.x * m.x, 0.0) * (4.0 / max(historyLength, 1.0));
    outIllumination = vec4(centre.rgb, variance);
}
