// Reads the GGX energy tables (bsdf/ggx_energy.glsl) through their uniform block, so tests can
// compare them with the C++ twin's arrays: per pixel (x, y) of a 65 x 65 target, the entries at
// i = (65 y + x) mod 512 (mod 32 for the averages) and the lookups at mu = x / 64, roughness = y / 64
// (exact in a float), which cover every cell of the tables and their edges.
#include "bsdf/ggx_energy.glsl"

out vec4 outEntries; // GGX_ALBEDO_TABLE[i], GGX_FRESNEL_ALBEDO_TABLE[i], the two averages' [i mod 32]
out vec4 outLookups; // ggxDirectionalAlbedo, ggxFresnelAlbedo, ggxAverageSchlickAlbedo(f0).x, ggxMultipleScatteringScale(f0).x

void main() {
    int x = int(gl_FragCoord.x);
    int y = int(gl_FragCoord.y);
    int i = (y * 65 + x) % 512;
    outEntries = vec4(ggxAlbedoAt(i), ggxFresnelAlbedoAt(i), ggxAverageAlbedoAt(i % 32), ggxAverageFresnelAlbedoAt(i % 32));
    float mu = float(x) * 0.015625f;
    float roughness = float(y) * 0.015625f;
    vec3 f0 = vec3(0.04f, 0.5f, 1.0f);
    outLookups = vec4(ggxDirectionalAlbedo(mu, roughness), ggxFresnelAlbedo(mu, roughness),
                      ggxAverageSchlickAlbedo(f0, roughness).x, ggxMultipleScatteringScale(f0, mu, roughness).x);
}
