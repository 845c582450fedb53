// Exposure, a tone curve and an explicit sRGB encode (never GL_FRAMEBUFFER_SRGB).
#include "tonemap_curves.glsl"

uniform sampler2D uRadiance;
uniform float uExposureScale; // 2^EV
uniform int uTonemapper;      // 0 none, 1 ACES fitted, 2 Khronos PBR Neutral, 3 AgX, 4 Reinhard, 5 Hable

out vec4 outColor;

void main() {
    vec4 radiance = texelFetch(uRadiance, ivec2(gl_FragCoord.xy), 0);
    vec3 mapped = applyTonemapper(radiance.rgb * uExposureScale, uTonemapper);
    outColor = vec4(encodeSrgb(clamp(mapped, 0.0, 1.0)), clamp(radiance.a, 0.0, 1.0));
}
