// Triangle meshes through the two-level BVH (shaders/bvh), compiled only for scenes with meshes
// (HAS_MESHES). Shading normals are interpolated vertex normals (the geometric normal where a mesh
// has none or they are degenerate), turned to the geometric normal's side.
#include "trace_state.glsl" // outside the #ifdef: the include resolver pastes a file only once
#ifdef HAS_TEXTURES
#include "textured_surface.glsl" // outside HAS_MESHES likewise: analytic shapes are textured too
#endif
#ifdef HAS_MESHES
#include "bvh/buffers.glsl"

// Mesh-local vertex data in the vertex order of bvh_layout.h, VERTEX_TEXELS per vertex: the normal;
// with textures (HAS_TEXTURES) also (uv0, uv1), the tangent and COLOR_0 (gpu_meshes.cpp).
uniform samplerBuffer uVertexNormals;
#ifdef HAS_TEXTURES
const int VERTEX_TEXELS = 4;
#else
const int VERTEX_TEXELS = 1;
#endif

vec4 vertexTexel(uint vertex, int k) { return texelFetch(uVertexNormals, int(vertex) * VERTEX_TEXELS + k); }

#ifdef HAS_TEXTURES
#include "mesh_surface.glsl"
#endif
#if defined(HAS_ALPHA) || defined(HAS_SINGLE_SIDED)
#define BVH_TRIANGLE_FILTER
#include "triangle_filter.glsl"
#endif
#include "bvh/traverse.glsl"

vec3 meshShadingNormal(BvhHit b, uvec4 vertices, vec3 geometricNormal) {
    vec3 local = (1.0 - b.u - b.v) * vertexTexel(vertices.x, 0).xyz + b.u * vertexTexel(vertices.y, 0).xyz +
                 b.v * vertexTexel(vertices.z, 0).xyz;
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
              float(bvhInstanceInfo(b.instance).z), true, ivec2(b.slot, b.instance), vec2(b.u, b.v));
}

bool occludedByMeshes(Ray ray, float distance) {
    return bvhOccluded(ray.origin, ray.direction, distance);
}
#endif
