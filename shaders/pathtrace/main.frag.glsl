// Path tracing pass: one sample per pixel into seven targets (radiance, albedo, normal + depth, id,
// diffuse albedo, specular albedo + roughness, specular radiance).
#include "constants.glsl"
#include "common/rng.glsl"
#include "ray.glsl"
#include "common/frame.glsl"
#include "scene_buffers.glsl"
#include "shapes.glsl"
#include "meshes.glsl"
#include "scene_trace.glsl"
#include "material.glsl"
#include "bsdf/bsdf.glsl"
#include "sampling/warp.glsl"
#include "sampling/mis.glsl"
#include "environment.glsl"
#include "lights.glsl"
#include "emissive_lights.glsl"
#ifdef HAS_EMISSIVE_SHAPES
#include "sampling/shape_emitter.glsl"
#include "shape_lights.glsl"
#endif
#include "media.glsl"
#ifdef HAS_PORTALS
#include "portals.glsl"
#endif
#include "camera.glsl"
#include "render_passes.glsl"
#include "lobe_radiance.glsl"
#include "integrator.glsl"
#include "output_guard.glsl"
#include "albedo_split.glsl"
#ifdef DEBUG_VIEW_BVH_COST
#include "bvh_cost.glsl"
#endif

uniform uint uSampleIndex;
uniform uint uSeed;
uniform uint uSampleBlock; // 1: every pixel its own sequence

out vec4 outRadiance;
out vec4 outAlbedo;
out vec4 outNormalDepth;
out vec4 outObjectId;
out vec4 outDiffuseAlbedo;  // what the diffuse lobe reflects: SVGF demodulates by diffuse + specular
out vec4 outSpecularAlbedo; // rgb: approximate directional albedo of the specular lobes; a: roughness
// The part of outRadiance the first hit's specular lobes carried (lobe_radiance.glsl); the rest is
// the diffuse part. Only the SPLIT_LOBES variant (the SVGF configurations) writes it: elsewhere it
// is 0 and the split compiles away. DEBUG_VIEW_DIFFUSE writes the diffuse part into outRadiance.
// a: the first bounce's reflection distance (LobeRadiance) in the SPLIT_LOBES variant, else 1.
out vec4 outSpecularRadiance;
#ifdef RENDER_PASSES
// The RENDER_PASSES variant (render_passes.glsl; offline Accumulate/Reference only, where nothing
// reads the denoiser's targets 4-6) writes the passes there instead: diffuse albedo = DiffDir,
// specular albedo = DiffInd, specular radiance = GlossDir, each with one channel of Emit in a;
// objectId.yzw = Env; and an eighth target, GlossInd. renderer/passes/render_passes_pass.h
// averages them.
out vec4 outGlossyIndirect;

// A pass of a sample whose radiance was dropped (output_guard.glsl) is dropped with it.
vec3 guardedPass(vec3 pass, bool kept) { return kept ? finiteNonNegative(pass) : vec3(0.0); }
#endif

void main() {
    uvec2 pixel = uvec2(gl_FragCoord.xy);
    // Owen-scrambled Sobol' points per pixel, or per block of pixels (uSampleBlock: one sequence for
    // the block, so its paths stay together and SIMD lanes wait less); common/rng.glsl. The
    // independent sampler (statistical tests: every sample independent) hashes each draw.
    Rng rng = uIndependentSampler != 0 ? rngStart(pixel, uSampleIndex, uSeed)
                                       : rngStartLowDiscrepancy(pixel / uSampleBlock, uSampleIndex, uSeed);
    Ray ray = cameraRay(pixel, rng);
    LobeRadiance lobes = noLobeRadiance();
#if defined(DEBUG_VIEW_BVH_COST)
    PathResult path = bvhCost(ray, cameraForward(), rng);
#elif defined(DEBUG_VIEW_AO)
    PathResult path = ambientOcclusion(ray, cameraForward(), rng);
#else
    PathResult path = tracePath(ray, cameraForward(), rng, lobes);
#endif
    outRadiance = vec4(finiteNonNegative(path.radiance), 1.0);
    outSpecularRadiance = vec4(guardedSpecular(lobes.specular, outRadiance.rgb), guardedReflectionDistance(lobes.reflectionDistance));
#ifdef DEBUG_VIEW_DIFFUSE
    outRadiance = vec4(finiteNonNegative(lobes.diffuse), 1.0);
    outSpecularRadiance.rgb = finiteNonNegative(lobes.specular);
#endif
    outAlbedo = vec4(finiteNonNegative(path.albedo), 1.0);
    outNormalDepth = vec4(finiteOrZero(path.normal), path.depth);
    outObjectId = vec4(path.objectId, 0.0, 0.0, 1.0);
    outDiffuseAlbedo = vec4(finiteNonNegative(diffuseAlbedo(path)), 1.0);
    outSpecularAlbedo = vec4(finiteNonNegative(specularAlbedo(path)), path.lobes.y);
#ifdef RENDER_PASSES
    bool kept = outRadiance.rgb == path.radiance;
    vec3 emission = guardedPass(gPasses.emission, kept);
    outObjectId.yzw = guardedPass(gPasses.environment, kept);
    outDiffuseAlbedo = vec4(guardedPass(gPasses.diffuseDirect, kept), emission.r);
    outSpecularAlbedo = vec4(guardedPass(gPasses.diffuseIndirect, kept), emission.g);
    outSpecularRadiance = vec4(guardedPass(gPasses.glossyDirect, kept), emission.b);
    outGlossyIndirect = vec4(guardedPass(gPasses.glossyIndirect, kept), 0.0);
#endif
}
