// Render passes for the EXR (the RENDER_PASSES variant, offline Accumulate/Reference renders
// only; docs/CLI.md, "Render passes"). Every contribution the integrator adds to the radiance is
// also added to exactly one pass, so the passes partition the beauty and sum to it up to float
// rounding. By the first hit's lobe and the path's length:
// - Emit: emission of what the camera ray hits (surfaces, emissive shapes, area lights, sphere lamps);
// - Env: the environment (and sun disk) where the camera ray leaves the scene;
// - DiffDir / GlossDir: direct light at the first hit through its diffuse lobe / its other lobes
//   (metal, the dielectric layer, glass reflection and transmission): next-event estimation at the
//   first hit (each light sample split by the diffuse lobe's share of the BSDF value, as SVGF's
//   lobe split) plus the emission (emitters, lamps, environment) that the first hit's BSDF sample
//   finds at the second vertex, both MIS-weighted;
// - DiffInd / GlossInd: everything else, by the lobe the first hit's BSDF sample took.
// Without RENDER_PASSES the hooks are empty and the integrator compiles as before.
#ifdef RENDER_PASSES
struct RenderPasses {
    vec3 diffuseDirect;
    vec3 diffuseIndirect;
    vec3 glossyDirect;
    vec3 glossyIndirect;
    vec3 emission;
    vec3 environment;
};

RenderPasses gPasses = RenderPasses(vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));

// Light a ray found at path vertex `depth` (0: the camera ray): an emitter, a lamp or the environment.
void passFound(int depth, vec3 c, bool specular, bool environment) {
    if (depth == 0) {
        if (environment) gPasses.environment += c;
        else gPasses.emission += c;
    } else if (depth == 1) {
        if (specular) gPasses.glossyDirect += c;
        else gPasses.diffuseDirect += c;
    } else {
        if (specular) gPasses.glossyIndirect += c;
        else gPasses.diffuseIndirect += c;
    }
}

// Next-event estimation at vertex `depth`: `c`, of which `diffuse` through the first hit's diffuse lobe.
void passLightSampled(int depth, vec3 c, vec3 diffuse, bool specular) {
    if (depth == 0) {
        gPasses.diffuseDirect += diffuse;
        gPasses.glossyDirect += c - diffuse;
    } else if (specular) {
        gPasses.glossyIndirect += c;
    } else {
        gPasses.diffuseIndirect += c;
    }
}

// The per-sample clamp scales every pass as it scaled the radiance (per channel).
void passesScale(vec3 scale) {
    gPasses.diffuseDirect *= scale;
    gPasses.diffuseIndirect *= scale;
    gPasses.glossyDirect *= scale;
    gPasses.glossyIndirect *= scale;
    gPasses.emission *= scale;
    gPasses.environment *= scale;
}
#define PASS_FOUND(depth, c, specular, environment) passFound(depth, c, specular, environment)
#define PASS_LIGHT_SAMPLED(depth, c, diffuse, specular) passLightSampled(depth, c, diffuse, specular)
#define PASSES_SCALE(scale) passesScale(scale)
#else
#define PASS_FOUND(depth, c, specular, environment)
#define PASS_LIGHT_SAMPLED(depth, c, diffuse, specular)
#define PASSES_SCALE(scale)
#endif
