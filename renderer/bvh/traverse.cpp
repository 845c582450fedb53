#include "renderer/bvh/traverse.h"

#include "renderer/bvh/bvh_layout.h"
#include "renderer/bvh/triangle_intersect.h"

#include <bit>
#include <limits>

namespace glint::bvh {
namespace {

constexpr float kMissed = std::numeric_limits<float>::infinity();
// Widens the far distance of box tests by 2 gamma(3) so rounding never culls a box the ray
// touches (Ize, "Robust BVH Ray Traversal", JCGT 2013).
constexpr float kFarWidening = 1.0f + 2.0f * 3.0f * std::numeric_limits<float>::epsilon();

// A level's ray for box tests: the grid its node boxes are on comes with it.
struct BoxRay {
    glm::vec3 origin;
    glm::vec3 inverseDirection;
    BoxGrid grid;
};

BoxRay boxRay(const FlatScene& scene, std::uint32_t level, const Ray& ray)
{
    return {ray.origin, 1.0f / ray.direction, levelGrid(scene, level)};
}

// Where the ray enters node's box within [0, tMax], or kMissed. A NaN slab constrains nothing.
float boxEntry(const FlatScene& scene, std::uint32_t node, const BoxRay& ray, float tMax)
{
    const Aabb box = nodeBox(scene, ray.grid, node);
    const glm::vec3 t0 = (box.lo - ray.origin) * ray.inverseDirection;
    const glm::vec3 t1 = (box.hi - ray.origin) * ray.inverseDirection;
    float nearT = 0.0f;
    float farT = tMax;
    for (int axis = 0; axis < 3; ++axis) {
        const float enter = t0[axis] < t1[axis] ? t0[axis] : t1[axis];
        const float leave = t0[axis] > t1[axis] ? t0[axis] : t1[axis];
        if (enter > nearT) nearT = enter;
        if (leave < farT) farT = leave;
    }
    return nearT <= farT * kFarWidening ? nearT : kMissed;
}

Ray localRay(const FlatScene& scene, std::uint32_t instance, const Ray& world)
{
    Ray local;
    for (int r = 0; r < 3; ++r) {
        const glm::uvec4 bits = scene.instances[kInstanceTexels * instance + r];
        const glm::vec4 row{std::bit_cast<float>(bits.x), std::bit_cast<float>(bits.y), std::bit_cast<float>(bits.z),
                            std::bit_cast<float>(bits.w)};
        local.origin[r] = row.x * world.origin.x + row.y * world.origin.y + row.z * world.origin.z + row.w;
        local.direction[r] = row.x * world.direction.x + row.y * world.direction.y + row.z * world.direction.z;
    }
    return local;
}

// Both levels share one stack: room for a full top-level walk and a full mesh walk above it.
constexpr int kTraversalStack = 2 * kStackSize;

// One loop over both levels with one stack, as the shader does: a top-level leaf (an instance)
// pushes its mesh's root above the top-level entries and switches to the mesh-local ray; when the
// stack falls back to that mark the walk is at the top level again. Nearer child first; the next
// node (nearer child, a mesh's root) is kept out of the stack, as the shader keeps it.
// onTriangle(instance, slot, hit) and onShape(instance, shape, localRay) return true to stop; they
// may lower tMax (closest hit).
template <class OnTriangle, class OnShape>
void walkScene(const FlatScene& scene, const Ray& worldRay, float& tMax, OnTriangle&& onTriangle, OnShape&& onShape,
               TraversalCost* cost = nullptr)
{
    TraversalCost unused;
    TraversalCost& counted = cost ? *cost : unused;
    if (scene.topLevel < 0) return;
    const auto top = static_cast<std::uint32_t>(scene.topLevel);
    const BoxRay worldBox = boxRay(scene, top, worldRay);
    const std::uint32_t topRoot = levelRootNode(scene, top);
    const float rootNear = boxEntry(scene, topRoot, worldBox, tMax);
    if (rootNear == kMissed) return;
    std::uint32_t stackNode[kTraversalStack];
    float stackNear[kTraversalStack];
    int size = 0;
    const auto push = [&](std::uint32_t entry, float nearT) {
        if (nearT == kMissed || size == kTraversalStack) return false;
        stackNode[size] = entry;
        stackNear[size++] = nearT;
        return true;
    };
    std::int64_t node = topRoot; // the next node to visit; -1: take it from the stack
    float nodeNear = rootNear;
    std::int64_t instance = -1; // the mesh instance being walked; -1 at the top level
    int meshMark = 0;           // stack size below the mesh's entries
    BoxRay box = worldBox;
    WatertightRay triangleRay = prepareWatertight(worldRay);
    for (int steps = 1; (node >= 0 || size > 0) && steps <= kMaxTraversalSteps; ++steps) {
        if (node < 0) {
            if (instance >= 0 && size == meshMark) {
                instance = -1;
                box = worldBox;
            }
            --size;
            node = stackNode[size];
            nodeNear = stackNear[size];
        }
        const auto current = static_cast<std::uint32_t>(node);
        node = -1;
        if (nodeNear > tMax) continue;
        ++counted.nodes;
        const glm::uvec2 link = nodeLink(scene, current);
        if (link.y > 0 && instance >= 0) {
            for (std::uint32_t slot = link.x; slot < link.x + link.y; ++slot) {
                TriangleHit hit;
                ++counted.primitives;
                const auto p = [&](int k) { return glm::vec3(scene.trianglePositions[kTrianglePositionTexels * slot + k]); };
                if (intersectTriangle(triangleRay, p(0), p(1), p(2), 0.0f, tMax, hit) &&
                    onTriangle(static_cast<std::uint32_t>(instance), slot, hit))
                    return;
            }
            continue;
        }
        if (link.y > 0) {
            const glm::uvec4 info = scene.instances[kInstanceTexels * link.x + 3];
            const Ray local = localRay(scene, link.x, worldRay);
            if (info.x == kInstanceShape) {
                ++counted.primitives;
                if (onShape(link.x, info.y, local)) return;
                continue;
            }
            // The mesh's root comes next without a box test of its own, as in the shader.
            meshMark = size;
            node = levelRootNode(scene, info.y);
            instance = link.x;
            box = boxRay(scene, info.y, local);
            triangleRay = prepareWatertight(local);
            continue;
        }
        const float nearLeft = boxEntry(scene, link.x, box, tMax);
        const float nearRight = boxEntry(scene, link.x + 1, box, tMax);
        const bool leftFirst = nearLeft <= nearRight;
        push(leftFirst ? link.x + 1 : link.x, leftFirst ? nearRight : nearLeft); // the farther one waits
        const float nearNear = leftFirst ? nearLeft : nearRight;
        if (nearNear != kMissed) {
            node = leftFirst ? link.x : link.x + 1;
            nodeNear = nearNear;
        }
    }
}

} // namespace

RayHit intersectClosest(const FlatScene& scene, const Ray& worldRay, float tMax, const ShapeIntersector& shapes,
                        TraversalCost* cost)
{
    RayHit result;
    walkScene(
        scene, worldRay, tMax,
        [&](std::uint32_t instance, std::uint32_t slot, const TriangleHit& hit) {
            tMax = hit.t;
            result = RayHit{hit.t, hit.u, hit.v, static_cast<std::int32_t>(instance), static_cast<std::int32_t>(slot),
                            static_cast<std::int32_t>(scene.slotTriangle[slot])};
            return false;
        },
        [&](std::uint32_t instance, std::uint32_t shape, const Ray& local) {
            if (shapes && shapes(shape, local, tMax))
                result = RayHit{tMax, 0.0f, 0.0f, static_cast<std::int32_t>(instance), -1, -1};
            return false;
        },
        cost);
    return result;
}

bool occluded(const FlatScene& scene, const Ray& worldRay, float tMax, const ShapeIntersector& shapes, TraversalCost* cost)
{
    bool blocked = false;
    walkScene(
        scene, worldRay, tMax, [&](std::uint32_t, std::uint32_t, const TriangleHit&) { return blocked = true; },
        [&](std::uint32_t, std::uint32_t shape, const Ray& local) {
            float limit = tMax;
            return blocked = shapes && shapes(shape, local, limit);
        },
        cost);
    return blocked;
}

} // namespace glint::bvh
