// Two-level BVH traversal: closest hit (bvhIntersectScene) and any hit (bvhOccluded). Twin of
// renderer/bvh/traverse.cpp. Rays are in world space; t is the world ray's parameter in both
// levels (local directions stay unnormalised). Every loop shares one step budget, so a NaN ray or
// a corrupt buffer ends after BVH_MAX_STEPS nodes.
//
// Shape instances: define BVH_SHAPE_INSTANCES and, before including this file,
//   bool bvhIntersectShapeInstance(uint shape, vec3 localOrigin, vec3 localDirection, inout float tMax);
// (lowers tMax and returns true on a closer hit). Without it shape instances are skipped.
//
// Triangle filter (alpha testing, back-face culling): define BVH_TRIANGLE_FILTER and, before
// including this file, bool bvhAcceptTriangle(int instance, int slot, vec3 tuv, vec3 localDirection);
// a rejected triangle hit is skipped as if the ray had missed it (closest and any hit alike).
#include "bvh/buffers.glsl"
#include "bvh/box.glsl"
#include "bvh/triangle.glsl"
#include "bvh/ray_offset.glsl"

struct BvhHit {
    float t;
    float u;      // barycentric weight of vertex 1
    float v;      // barycentric weight of vertex 2
    int instance; // -1: no hit
    int slot;     // triangle slot; -1 for a shape instance
};

BvhHit bvhNoHit(float tMax) { return BvhHit(tMax, 0.0, 0.0, -1, -1); }

void bvhLocalRay(int instance, vec3 origin, vec3 direction, out vec3 localOrigin, out vec3 localDirection) {
    for (int r = 0; r < 3; ++r) {
        precise vec4 row = bvhInstanceRow(instance, r);
        localOrigin[r] = row.x * origin.x + row.y * origin.y + row.z * origin.z + row.w;
        localDirection[r] = row.x * direction.x + row.y * direction.y + row.z * direction.z;
    }
}

// Walks one mesh BVH from `root`, nearer child first. anyHit: stop at the first hit.
// Returns false when the step budget ran out.
bool bvhWalkMesh(int root, int instance, vec3 origin, vec3 direction, bool anyHit, inout BvhHit hit, inout int steps) {
    vec3 inverseDirection = 1.0 / direction;
    BvhWatertightRay ray = bvhPrepareWatertight(origin, direction);
    int stackNode[BVH_STACK_SIZE];
    float stackNear[BVH_STACK_SIZE];
    int size = 0;
    float rootNear = bvhBoxEntry(root, origin, inverseDirection, hit.t);
    if (rootNear < 0.0) return true;
    stackNode[0] = root;
    stackNear[0] = rootNear;
    size = 1;
    while (size > 0) {
        if (++steps > BVH_MAX_STEPS) return false;
        --size;
        if (stackNear[size] > hit.t) continue;
        uvec4 link = bvhNodeLink(stackNode[size]);
        if (link.y > 0u) {
            for (int slot = int(link.x); slot < int(link.x + link.y); ++slot) {
                vec3 tuv;
                if (bvhIntersectTriangle(ray, bvhTrianglePosition(slot, 0), bvhTrianglePosition(slot, 1),
                                         bvhTrianglePosition(slot, 2), hit.t, tuv)) {
#ifdef BVH_TRIANGLE_FILTER
                    if (!bvhAcceptTriangle(instance, slot, tuv, direction)) continue;
#endif
                    hit = BvhHit(tuv.x, tuv.y, tuv.z, instance, slot);
                    if (anyHit) return true;
                }
            }
            continue;
        }
        int left = int(link.x);
        float nearLeft = bvhBoxEntry(left, origin, inverseDirection, hit.t);
        float nearRight = bvhBoxEntry(left + 1, origin, inverseDirection, hit.t);
        bool leftFirst = nearLeft <= nearRight || nearRight < 0.0;
        // Push the farther child first so the nearer one is popped next.
        int farNode = leftFirst ? left + 1 : left;
        float farNear = leftFirst ? nearRight : nearLeft;
        int nearNode = leftFirst ? left : left + 1;
        float nearNear = leftFirst ? nearLeft : nearRight;
        if (farNear >= 0.0 && size < BVH_STACK_SIZE) { stackNode[size] = farNode; stackNear[size] = farNear; ++size; }
        if (nearNear >= 0.0 && size < BVH_STACK_SIZE) { stackNode[size] = nearNode; stackNear[size] = nearNear; ++size; }
    }
    return true;
}

void bvhVisitInstance(int instance, vec3 origin, vec3 direction, bool anyHit, inout BvhHit hit, inout int steps,
                      inout bool budgetLeft) {
    uvec4 info = bvhInstanceInfo(instance);
    vec3 localOrigin;
    vec3 localDirection;
    bvhLocalRay(instance, origin, direction, localOrigin, localDirection);
    if (info.x == BVH_INSTANCE_MESH) {
        budgetLeft = bvhWalkMesh(int(info.y), instance, localOrigin, localDirection, anyHit, hit, steps);
    }
#ifdef BVH_SHAPE_INSTANCES
    else if (info.x == BVH_INSTANCE_SHAPE) {
        float t = hit.t;
        if (bvhIntersectShapeInstance(info.y, localOrigin, localDirection, t)) hit = BvhHit(t, 0.0, 0.0, instance, -1);
    }
#endif
}

// The top level: the same walk over instance boxes in world space.
BvhHit bvhTraverse(vec3 origin, vec3 direction, float tMax, bool anyHit) {
    BvhHit hit = bvhNoHit(tMax);
    if (uBvhTopLevelRoot < 0) return hit;
    vec3 inverseDirection = 1.0 / direction;
    int steps = 0;
    bool budgetLeft = true;
    int stackNode[BVH_STACK_SIZE];
    float stackNear[BVH_STACK_SIZE];
    float rootNear = bvhBoxEntry(uBvhTopLevelRoot, origin, inverseDirection, hit.t);
    if (rootNear < 0.0) return hit;
    stackNode[0] = uBvhTopLevelRoot;
    stackNear[0] = rootNear;
    int size = 1;
    while (size > 0 && budgetLeft) {
        if (++steps > BVH_MAX_STEPS) break;
        --size;
        if (stackNear[size] > hit.t) continue;
        uvec4 link = bvhNodeLink(stackNode[size]);
        if (link.y > 0u) {
            bvhVisitInstance(int(link.x), origin, direction, anyHit, hit, steps, budgetLeft);
            if (anyHit && hit.instance >= 0) break;
            continue;
        }
        int left = int(link.x);
        float nearLeft = bvhBoxEntry(left, origin, inverseDirection, hit.t);
        float nearRight = bvhBoxEntry(left + 1, origin, inverseDirection, hit.t);
        bool leftFirst = nearLeft <= nearRight || nearRight < 0.0;
        int farNode = leftFirst ? left + 1 : left;
        float farNear = leftFirst ? nearRight : nearLeft;
        int nearNode = leftFirst ? left : left + 1;
        float nearNear = leftFirst ? nearLeft : nearRight;
        if (farNear >= 0.0 && size < BVH_STACK_SIZE) { stackNode[size] = farNode; stackNear[size] = farNear; ++size; }
        if (nearNear >= 0.0 && size < BVH_STACK_SIZE) { stackNode[size] = nearNode; stackNear[size] = nearNear; ++size; }
    }
    return hit;
}

// Closest hit with 0 < t < tMax; hit.instance < 0 when nothing is hit.
BvhHit bvhIntersectScene(vec3 origin, vec3 direction, float tMax) { return bvhTraverse(origin, direction, tMax, false); }

// Anything between 0 and tMax (shadow rays).
bool bvhOccluded(vec3 origin, vec3 direction, float tMax) { return bvhTraverse(origin, direction, tMax, true).instance >= 0; }

// World-space unit geometric normal of a triangle hit: cross(p1 - p0, p2 - p0) in the mesh's space
// through the transposed inverse, so it marks the front face as glTF defines it even for mirrored
// instances (whose world-space winding is clockwise). Not faced towards the ray.
vec3 bvhGeometricNormal(BvhHit hit) {
    vec3 p0 = bvhTrianglePosition(hit.slot, 0);
    vec3 localNormal = cross(bvhTrianglePosition(hit.slot, 1) - p0, bvhTrianglePosition(hit.slot, 2) - p0);
    return bvhNormalToWorld(hit.instance, localNormal);
}
