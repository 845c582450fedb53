// Traces one ray per pixel, read from buffers, through the two-level BVH: closest hit and shadow
// query. Lets tests hold the GLSL traversal against its CPU twin (renderer/bvh/traverse.cpp).
#include "bvh/traverse.glsl"

uniform samplerBuffer uRayOrigins;    // RGBA32F per ray: (origin.xyz, tMax)
uniform samplerBuffer uRayDirections; // RGBA32F per ray: (direction.xyz, 0)
uniform int uRayQueryWidth;           // rays per row of the target

out vec4 outHit;      // (t, u, v, slot)
out vec4 outInstance; // (instance, occluded ? 1 : 0, object id, 0)

void main() {
    int index = int(gl_FragCoord.y) * uRayQueryWidth + int(gl_FragCoord.x);
    vec4 origin = texelFetch(uRayOrigins, index);
    vec3 direction = texelFetch(uRayDirections, index).xyz;
    BvhHit hit = bvhIntersectScene(origin.xyz, direction, origin.w);
    bool blocked = bvhOccluded(origin.xyz, direction, origin.w);
    float objectId = hit.instance >= 0 ? float(bvhInstanceInfo(hit.instance).z) : 0.0;
    outHit = vec4(hit.t, hit.u, hit.v, float(hit.slot));
    outInstance = vec4(float(hit.instance), blocked ? 1.0 : 0.0, objectId, 0.0);
}
