// Mean denoiser, stage 3: the filtered illumination times the surface's albedo again; misses keep
// the mean's radiance, and alpha (coverage) is the mean's.
#include "reconstruction/svgf_demodulate.glsl"

uniform sampler2D uIllumination;
uniform sampler2D uRadiance;
uniform sampler2D uDiffuseAlbedo;
uniform sampler2D uSpecularAlbedo;
uniform sampler2D uNormalDepth;

out vec4 outRadiance;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 mean = texelFetch(uRadiance, pixel, 0);
    vec3 illumination = texelFetch(uIllumination, pixel, 0).rgb;
    if (texelFetch(uNormalDepth, pixel, 0).w < 0.0) {
        outRadiance = mean;
        return;
    }
    vec3 albedo = texelFetch(uDiffuseAlbedo, pixel, 0).rgb + texelFetch(uSpecularAlbedo, pixel, 0).rgb;
    outRadiance = vec4(remodulate(illumination, albedo), mean.a);
}
