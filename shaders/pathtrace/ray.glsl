// Rays and hit records in world space.
#include "bvh/ray_offset.glsl"

struct Ray {
    vec3 origin;
    vec3 direction; // unit length
};

struct Hit {
    float t;
    vec3 geometricNormal; // unit, world space, not yet faced towards the ray
    vec3 shadingNormal;   // unit, world space, on the same side as geometricNormal
    int material;         // index into the material buffer; -1: no hit
    float objectId;       // node id of what was hit
    bool onMesh;          // a mesh triangle (emissive ones are also sampled as lights)
    ivec2 triangle;       // mesh hits: (triangle slot, instance); shapes: (-1, shape index); else (-1, -1)
    vec2 barycentric;     // mesh hits: weights of vertices 1 and 2; shapes: their UV (HAS_TEXTURES, shape_uv.glsl)
};

Hit noHit() {
    return Hit(RAY_MAX, vec3(0.0, 1.0, 0.0), vec3(0.0, 1.0, 0.0), -1, 0.0, false, ivec2(-1), vec2(0.0));
}

// Secondary rays start a few ULPs off the surface (bvh/ray_offset.glsl): no self-intersection, at
// any coordinate magnitude, on the side of the face normal the ray leaves through.
Ray spawnRay(vec3 p, vec3 faceNormal, vec3 direction) {
    vec3 side = dot(direction, faceNormal) >= 0.0 ? faceNormal : -faceNormal;
    return Ray(bvhOffsetRayOrigin(p, side), direction);
}
