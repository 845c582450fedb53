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

// One level's ray, and the grid its node boxes are on.
struct BvhLevelRay {
    vec3 origin;
    vec3 direction;
    vec3 inverse;
    vec3 gridOrigin;
    vec3 gridScale;
};

// One walk over both levels with one stack: a top-level leaf (an instance) pushes its mesh's root
// above the top-level entries and switches to the mesh-local ray; when the stack falls back to that
// mark, the walk is at the top level again. Nearer child first; anyHit: stop at the first hit. The
// node to visit next (the nearer child, a mesh's root) stays in the walk; only farther children are
// pushed (run-time indexed stack accesses are gathers and scatters across llvmpipe's SIMD lanes).
// Nodes are handled by their packed links, each in one texel with its grid box, so a step fetches
// one texel per child and nothing else.
//
// Interior nodes and leaves take turns ("while-while", Aila and Laine 2009): bvhDescend walks
// interior nodes until every lane stands at a leaf or has finished, then each lane at a leaf tests
// its triangles or enters its instance. llvmpipe runs every branch of a loop body for all lanes,
// masked, so a single loop paid for a leaf's triangle tests and an instance's transform at every
// interior step; here an interior step pays for two box tests only, and a nearer child that is a
// leaf is stood at in the same step. A pass of the outer loop enters an instance and descends its
// mesh before the triangle tests, so an instance and its first mesh leaf (the whole of a one-leaf
// mesh) cost one pass, not two. Each ray visits the same nodes in the same order as
// renderer/bvh/traverse.cpp, so hits are the same to the bit.
struct BvhWalk {
    int next;       // the packed link of the node to visit next; -1: take one from the stack
    float nextNear; // where the ray enters that node's box
    int size;       // stack entries
    int instance;   // the mesh instance being walked; -1 at the top level
    int meshMark;   // stack size below the mesh's entries
    BvhLevelRay ray; // the current level's
    int steps;
    int leaf;       // the packed link of the leaf the walk stands at; -1: none
};

// The stack lives outside bvhTraverse so that its two descents share it without a copy (GLSL passes
// arrays by value).
int bvhStackLink[BVH_TRAVERSAL_STACK];
float bvhStackNear[BVH_TRAVERSAL_STACK];

// Descends interior nodes, nearer child first, taking the next node from the stack where there is
// none, until the walk stands at a leaf or has nothing left (or has run out of steps). A walk already
// at a leaf stays there.
void bvhDescend(inout BvhWalk walk, BvhLevelRay worldRay, float tMax) {
    while (walk.leaf < 0 && (walk.next >= 0 || walk.size > 0)) {
        if (++walk.steps > BVH_MAX_STEPS) break;
        if (walk.next < 0) {
            if (walk.instance >= 0 && walk.size == walk.meshMark) {
                walk.instance = -1;
                walk.ray = worldRay;
            }
            --walk.size;
            walk.next = bvhStackLink[walk.size];
            walk.nextNear = bvhStackNear[walk.size];
        }
        int link = walk.next;
        walk.next = -1;
        if (walk.nextNear > tMax) continue;
        BVH_COUNT_NODE();
        if (bvhLinkCount(link) > 0) {
            walk.leaf = link;
            break;
        }
        int left = bvhLinkFirst(link);
        int leftLink;
        int rightLink;
        float nearLeft = bvhBoxEntry(left, walk.ray.gridOrigin, walk.ray.gridScale, walk.ray.origin, walk.ray.inverse, tMax, leftLink);
        float nearRight = bvhBoxEntry(left + 1, walk.ray.gridOrigin, walk.ray.gridScale, walk.ray.origin, walk.ray.inverse, tMax, rightLink);
        bool leftFirst = nearLeft <= nearRight || nearRight < 0.0;
        // The farther child waits on the stack; the nearer one is visited next, at once if a leaf.
        float farNear = leftFirst ? nearRight : nearLeft;
        if (farNear >= 0.0 && walk.size < BVH_TRAVERSAL_STACK) {
            bvhStackLink[walk.size] = leftFirst ? rightLink : leftLink;
            bvhStackNear[walk.size] = farNear;
            ++walk.size;
        }
        float nearNear = leftFirst ? nearLeft : nearRight;
        int nearLink = leftFirst ? leftLink : rightLink;
        if (nearNear < 0.0) continue;
        if (bvhLinkCount(nearLink) > 0) {
            ++walk.steps;
            BVH_COUNT_NODE();
            walk.leaf = nearLink;
            break;
        }
        walk.next = nearLink;
        walk.nextNear = nearNear;
    }
}

BvhHit bvhTraverse(vec3 origin, vec3 direction, float tMax, bool anyHit) {
    BvhHit hit = bvhNoHit(tMax);
    if (uBvhTopLevel < 0) return hit;
    BvhLevel top = bvhLevel(uBvhTopLevel);
    BvhLevelRay worldRay = BvhLevelRay(origin, direction, 1.0 / direction, top.gridOrigin, top.gridScale);
    int rootLink;
    float rootNear = bvhBoxEntry(top.rootNode, top.gridOrigin, top.gridScale, origin, worldRay.inverse, hit.t, rootLink);
    if (rootNear < 0.0) return hit;
    BvhWalk walk = BvhWalk(rootLink, rootNear, 0, -1, 0, worldRay, 0, -1);
    BvhWatertightRay triangleRay = bvhPrepareWatertight(origin, direction);
    while (true) {
        bvhDescend(walk, worldRay, hit.t);
        if (walk.leaf < 0) break; // nothing left, or out of steps
        if (walk.instance < 0) {
            int leafInstance = bvhLinkFirst(walk.leaf);
            walk.leaf = -1;
            uvec4 info = bvhInstanceInfo(leafInstance);
            vec3 localOrigin;
            vec3 localDirection;
            bvhLocalRay(leafInstance, origin, direction, localOrigin, localDirection);
            if (info.x == BVH_INSTANCE_MESH) {
                // The mesh's root comes next without a box test of its own: the instance's box, just
                // entered, bounds it, and the root's children are tested as usual.
                BvhLevel mesh = bvhLevel(int(info.y));
                walk.meshMark = walk.size;
                walk.next = mesh.root;
                walk.instance = leafInstance;
                walk.ray = BvhLevelRay(localOrigin, localDirection, 1.0 / localDirection, mesh.gridOrigin, mesh.gridScale);
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
        bvhDescend(walk, worldRay, hit.t); // into the mesh just entered
        if (walk.leaf < 0 || walk.instance < 0) continue; // a top-level leaf waits for the next pass
        int first = bvhLinkFirst(walk.leaf);
        int end = first + bvhLinkCount(walk.leaf);
        walk.leaf = -1;
        for (int slot = first; slot < end; ++slot) {
            vec3 tuv;
            BVH_COUNT_PRIMITIVE();
            if (bvhIntersectTriangle(triangleRay, bvhTrianglePosition(slot, 0), bvhTrianglePosition(slot, 1),
                                     bvhTrianglePosition(slot, 2), hit.t, tuv)) {
#ifdef BVH_TRIANGLE_FILTER
                if (!bvhAcceptTriangle(walk.instance, slot, tuv, walk.ray.direction)) continue;
#endif
                hit = BvhHit(tuv.x, tuv.y, tuv.z, walk.instance, slot);
                if (anyHit) return hit;
            }
        }
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
