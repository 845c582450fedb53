// Two-level BVH traversal: closest hit (bvhIntersectScene) and any hit (bvhOccluded). Twin of
// renderer/bvh/traverse.cpp. Rays are in world space; t is the world ray's parameter in both
// levels (local directions stay unnormalised). One loop walks both levels, so a NaN ray or a
// corrupt buffer ends after BVH_MAX_STEPS nodes.
//
// Shape instances: define BVH_SHAPE_INSTANCES and, before including this file,
//   bool bvhIntersectShapeInstance(uint shape, vec3 localOrigin, vec3 localDirection, inout float tMax);
// (lowers tMax and returns true on a closer hit). Without it shape instances are skipped.
//
// Triangle filter (alpha testing, back-face culling): define BVH_TRIANGLE_FILTER and, before
// including this file, bool bvhAcceptTriangle(int instance, int slot, vec3 tuv, vec3 localDirection);
// a rejected triangle hit is skipped as if the ray had missed it (closest and any hit alike).
//
// Cost counting (the BVH heat map, a debug variant): define BVH_COUNT_COST and the walk adds to
// bvhCostNodes (nodes taken off the stack and not culled, both levels) and bvhCostPrimitives
// (triangle and shape tests). Without the define the counters do not exist and the walk is the
// same code as before.
#include "bvh/buffers.glsl"
#include "bvh/box.glsl"
#include "bvh/triangle.glsl"
#include "bvh/ray_offset.glsl"

// Both levels share one stack: room for a full top-level walk and a full mesh walk above it.
const int BVH_TRAVERSAL_STACK = 2 * BVH_STACK_SIZE;

#ifdef BVH_COUNT_COST
int bvhCostNodes = 0;
int bvhCostPrimitives = 0;
#define BVH_COUNT_NODE() ++bvhCostNodes
#define BVH_COUNT_PRIMITIVE() ++bvhCostPrimitives
#else
#define BVH_COUNT_NODE()
#define BVH_COUNT_PRIMITIVE()
#endif

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

// One walk over both levels with one stack: a top-level leaf (an instance) pushes its mesh's root
// above the top-level entries and switches to the mesh-local ray; when the stack falls back to that
// mark, the walk is at the top level again. Nearer child first; anyHit: stop at the first hit. The
// node to visit next (the nearer child, a mesh's root) stays in `node`; only farther children are
// pushed (run-time indexed stack accesses are gathers and scatters across llvmpipe's SIMD lanes).
//
// Interior nodes and leaves take turns ("while-while", Aila and Laine 2009): an inner loop descends
// interior nodes until every lane stands at a leaf or has finished, then each lane at a leaf tests
// its triangles or enters its instance. llvmpipe runs every branch of a loop body for all lanes,
// masked, so a single loop paid for a leaf's triangle tests and an instance's transform at every
// interior step; here an interior step pays for two box tests only. Each ray visits the same nodes
// in the same order as before (and as renderer/bvh/traverse.cpp), so hits are the same to the bit.
BvhHit bvhTraverse(vec3 origin, vec3 direction, float tMax, bool anyHit) {
    BvhHit hit = bvhNoHit(tMax);
    if (uBvhTopLevelRoot < 0) return hit;
    vec3 worldInverse = 1.0 / direction;
    float rootNear = bvhBoxEntry(uBvhTopLevelRoot, origin, worldInverse, hit.t);
    if (rootNear < 0.0) return hit;
    int stackNode[BVH_TRAVERSAL_STACK];
    float stackNear[BVH_TRAVERSAL_STACK];
    int size = 0;
    int node = uBvhTopLevelRoot; // the next node to visit, -1: take it from the stack
    float nodeNear = rootNear;
    int instance = -1; // the mesh instance being walked; -1 at the top level
    int meshMark = 0;  // stack size below the mesh's entries
    vec3 rayOrigin = origin;
    vec3 rayDirection = direction;
    vec3 rayInverse = worldInverse;
    BvhWatertightRay triangleRay = bvhPrepareWatertight(origin, direction);
    int steps = 0;
    while (node >= 0 || size > 0) {
        bool atLeaf = false;
        uvec4 link;
        while (node >= 0 || size > 0) {
            if (++steps > BVH_MAX_STEPS) break;
            if (node < 0) {
                if (instance >= 0 && size == meshMark) {
                    instance = -1;
                    rayOrigin = origin;
                    rayDirection = direction;
                    rayInverse = worldInverse;
                }
                --size;
                node = stackNode[size];
                nodeNear = stackNear[size];
            }
            int current = node;
            node = -1;
            if (nodeNear > hit.t) continue;
            BVH_COUNT_NODE();
            link = bvhNodeLink(current);
            if (link.y > 0u) {
                atLeaf = true;
                break;
            }
            int left = int(link.x);
            float nearLeft = bvhBoxEntry(left, rayOrigin, rayInverse, hit.t);
            float nearRight = bvhBoxEntry(left + 1, rayOrigin, rayInverse, hit.t);
            bool leftFirst = nearLeft <= nearRight || nearRight < 0.0;
            // The farther child waits on the stack; the nearer one is visited next.
            int farNode = leftFirst ? left + 1 : left;
            float farNear = leftFirst ? nearRight : nearLeft;
            if (farNear >= 0.0 && size < BVH_TRAVERSAL_STACK) { stackNode[size] = farNode; stackNear[size] = farNear; ++size; }
            float nearNear = leftFirst ? nearLeft : nearRight;
            if (nearNear >= 0.0) {
                node = leftFirst ? left : left + 1;
                nodeNear = nearNear;
            }
        }
        if (!atLeaf) break; // nothing left, or out of steps
        if (instance >= 0) {
            for (int slot = int(link.x); slot < int(link.x + link.y); ++slot) {
                vec3 tuv;
                BVH_COUNT_PRIMITIVE();
                if (bvhIntersectTriangle(triangleRay, bvhTrianglePosition(slot, 0), bvhTrianglePosition(slot, 1),
                                         bvhTrianglePosition(slot, 2), hit.t, tuv)) {
#ifdef BVH_TRIANGLE_FILTER
                    if (!bvhAcceptTriangle(instance, slot, tuv, rayDirection)) continue;
#endif
                    hit = BvhHit(tuv.x, tuv.y, tuv.z, instance, slot);
                    if (anyHit) return hit;
                }
            }
            continue;
        }
        int leafInstance = int(link.x);
        uvec4 info = bvhInstanceInfo(leafInstance);
        vec3 localOrigin;
        vec3 localDirection;
        bvhLocalRay(leafInstance, origin, direction, localOrigin, localDirection);
        if (info.x == BVH_INSTANCE_MESH) {
            // The mesh's root comes next without a box test of its own: the instance's box, just
            // entered, bounds it, and the root's children are tested as usual.
            meshMark = size;
            node = int(info.y);
            instance = leafInstance;
            rayOrigin = localOrigin;
            rayDirection = localDirection;
            rayInverse = 1.0 / localDirection;
            triangleRay = bvhPrepareWatertight(localOrigin, localDirection);
        }
#ifdef BVH_SHAPE_INSTANCES
        else if (info.x == BVH_INSTANCE_SHAPE) {
            float t = hit.t;
            BVH_COUNT_PRIMITIVE();
            if (bvhIntersectShapeInstance(info.y, localOrigin, localDirection, t)) {
                hit = BvhHit(t, 0.0, 0.0, leafInstance, -1);
                if (anyHit) return hit;
            }
        }
#endif
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
