// SVGF stage 4: filtered illumination times albedo gives radiance again.
#include "reconstruction/svgf_demodulate.glsl"

uniform sampler2D uIllumination;
uniform sampler2D uDiffuseAlbedo;
uniform sampler2D uSpecularAlbedo;

out vec4 outRadiance;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    outRadiance = vec4(remodulate(texelFetch(uIllumination, pixel, 0).rgb, lobeAlbedo(uDiffuseAlbedo, uSpecularAlbedo, pixel)), 1.0);
}
