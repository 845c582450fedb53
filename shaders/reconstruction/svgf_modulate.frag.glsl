// SVGF stage 4: each lobe's filtered illumination times its albedo, summed, gives radiance again.
#include "reconstruction/svgf_demodulate.glsl"

uniform sampler2D uDiffuse;  // filtered illumination, rgb
uniform sampler2D uSpecular;
uniform sampler2D uDiffuseAlbedo;
uniform sampler2D uSpecularAlbedo;

out vec4 outRadiance;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 diffuse = remodulate(texelFetch(uDiffuse, pixel, 0).rgb, texelFetch(uDiffuseAlbedo, pixel, 0).rgb);
    vec3 specular = remodulate(texelFetch(uSpecular, pixel, 0).rgb, texelFetch(uSpecularAlbedo, pixel, 0).rgb);
    outRadiance = vec4(diffuse + specular, 1.0);
}
