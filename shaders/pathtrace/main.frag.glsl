// Path tracing pass: one sample per pixel into six targets (radiance, albedo, normal + depth, id,
// diffuse albedo, specular albedo + roughness).
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
#include "camera.glsl"
#include "integrator.glsl"
#include "output_guard.glsl"
#include "albedo_split.glsl"

uniform uint uSampleIndex;
uniform uint uSeed;

out vec4 outRadiance;
out vec4 outAlbedo;
out vec4 outNormalDepth;
out vec4 outObjectId;
out vec4 outDiffuseAlbedo;  // what the diffuse lobe reflects: SVGF demodulates by diffuse + specular
out vec4 outSpecularAlbedo; // rgb: approximate directional albedo of the specular lobes; a: roughness

void main() {
    uvec2 pixel = uvec2(gl_FragCoord.xy);
    Rng rng = rngStart(pixel, uSampleIndex, uSeed);
    Ray ray = cameraRay(pixel, uSampleIndex, uSeed, rng);
#ifdef DEBUG_VIEW_AO
    PathResult path = ambientOcclusion(ray, cameraForward(), rng);
#else
    PathResult path = tracePath(ray, cameraForward(), rng);
#endif
    outRadiance = vec4(finiteNonNegative(path.radiance), 1.0);
    outAlbedo = vec4(finiteNonNegative(path.albedo), 1.0);
    outNormalDepth = vec4(finiteOrZero(path.normal), path.depth);
    outObjectId = vec4(path.objectId, 0.0, 0.0, 1.0);
    outDiffuseAlbedo = vec4(finiteNonNegative(diffuseAlbedo(path)), 1.0);
    outSpecularAlbedo = vec4(finiteNonNegative(specularAlbedo(path)), path.lobes.y);
}
