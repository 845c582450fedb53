// Triangle meshes through the two-level BVH (shaders/bvh), compiled only for scenes with meshes
// (HAS_MESHES). Shading normals are interpolated vertex normals (the geometric normal where a mesh
// has none or they are degenerate), turned to the geometric normal's side.
#ifdef HAS_MESHES
#include "bvh/traverse.glsl"

uniform samplerBuffer uVertexNormals; // mesh-local, in the vertex order of bvh_layout.h

vec3 meshShadingNormal(BvhHit b, uvec4 vertices, vec3 geometricNormal) {
    vec3 local = (1.0 - b.u - b.v) * texelFetch(uVertexNormals, int(vertices.x)).xyz +
                 b.u * texelFetch(uVertexNormals, int(vertices.y)).xyz + b.v * texelFetch(uVertexNormals, int(vertices.z)).xyz;
    if (!(dot(local, local) > 1e-12) || !isFiniteVec3(local)) return geometricNormal;
    vec3 n = bvhNormalToWorld(b.instance, local);
    if (!isFiniteVec3(n)) return geometricNormal;
    return dot(n, geometricNormal) < 0.0 ? -n : n;
}

void intersectMeshes(Ray ray, INOUT(Hit) hit) {
    BvhHit b = bvhIntersectScene(ray.origin, ray.direction, hit.t);
    if (b.instance < 0 || b.slot < 0) return;
    uvec4 vertices = bvhTriangleVertices(b.slot);
    vec3 geometricNormal = bvhGeometricNormal(b);
    if (!isFiniteVec3(geometricNormal)) return; // a zero-area triangle the watertight test let through
    hit = Hit(b.t, geometricNormal, meshShadingNormal(b, vertices, geometricNormal), int(vertices.w),
              float(bvhInstanceInfo(b.instance).z), true);
}

bool occludedByMeshes(Ray ray, float distance) {
    return bvhOccluded(ray.origin, ray.direction, distance);
}
#endif
