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

struct BoxRay {
    glm::vec3 origin;
    glm::vec3 inverseDirection;
};

BoxRay boxRay(const Ray& ray)
{
    return {ray.origin, 1.0f / ray.direction};
}

// Where the ray enters node's box within [0, tMax], or kMissed. A NaN slab constrains nothing.
float boxEntry(const FlatScene& scene, std::uint32_t node, const BoxRay& ray, float tMax)
{
    const glm::vec3 t0 = (glm::vec3(scene.nodeBounds[2 * node]) - ray.origin) * ray.inverseDirection;
    const glm::vec3 t1 = (glm::vec3(scene.nodeBounds[2 * node + 1]) - ray.origin) * ray.inverseDirection;
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

struct Traversal {
    const FlatScene& scene;
    float tMax;
    int steps = 0;
};

// Walks one level from `root`, nearer child first. onLeaf(link) returns true to stop the walk
// (any-hit) and may lower traversal.tMax (closest hit).
template <class OnLeaf>
bool walkLevel(Traversal& traversal, std::uint32_t root, const Ray& ray, OnLeaf&& onLeaf)
{
    const BoxRay box = boxRay(ray);
    std::uint32_t stackNode[kStackSize];
    float stackNear[kStackSize];
    int size = 0;
    const float rootNear = boxEntry(traversal.scene, root, box, traversal.tMax);
    if (rootNear == kMissed) return false;
    stackNode[size] = root;
    stackNear[size++] = rootNear;
    const auto push = [&](std::uint32_t node, float nearT) {
        if (nearT == kMissed || size == kStackSize) return;
        stackNode[size] = node;
        stackNear[size++] = nearT;
    };
    while (size > 0) {
        if (++traversal.steps > kMaxTraversalSteps) return true;
        --size;
        if (stackNear[size] > traversal.tMax) continue;
        const glm::uvec4 link = traversal.scene.nodeLinks[stackNode[size]];
        if (link.y > 0) {
            if (onLeaf(link)) return true;
            continue;
        }
        const float nearLeft = boxEntry(traversal.scene, link.x, box, traversal.tMax);
        const float nearRight = boxEntry(traversal.scene, link.x + 1, box, traversal.tMax);
        if (nearLeft <= nearRight) {
            push(link.x + 1, nearRight);
            push(link.x, nearLeft);
        } else {
            push(link.x, nearLeft);
            push(link.x + 1, nearRight);
        }
    }
    return false;
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

// Tests the leaf's triangles; onHit(slot, hit) returns true to stop.
template <class OnHit>
bool intersectLeaf(Traversal& traversal, const WatertightRay& ray, glm::uvec4 link, OnHit&& onHit)
{
    const FlatScene& scene = traversal.scene;
    for (std::uint32_t slot = link.x; slot < link.x + link.y; ++slot) {
        TriangleHit hit;
        const auto p = [&](int k) { return glm::vec3(scene.trianglePositions[kTrianglePositionTexels * slot + k]); };
        if (intersectTriangle(ray, p(0), p(1), p(2), 0.0f, traversal.tMax, hit) && onHit(slot, hit)) return true;
    }
    return false;
}

// Visits every instance whose box the ray reaches; onInstance(instance, info, localRay) returns
// true to stop.
template <class OnInstance>
void walkScene(Traversal& traversal, const Ray& worldRay, OnInstance&& onInstance)
{
    if (traversal.scene.topLevelRoot < 0) return;
    walkLevel(traversal, static_cast<std::uint32_t>(traversal.scene.topLevelRoot), worldRay, [&](glm::uvec4 link) {
        const glm::uvec4 info = traversal.scene.instances[kInstanceTexels * link.x + 3];
        return onInstance(link.x, info, localRay(traversal.scene, link.x, worldRay));
    });
}

} // namespace

RayHit intersectClosest(const FlatScene& scene, const Ray& worldRay, float tMax, const ShapeIntersector& shapes)
{
    RayHit result;
    Traversal traversal{scene, tMax};
    walkScene(traversal, worldRay, [&](std::uint32_t instance, glm::uvec4 info, const Ray& local) {
        if (info.x == kInstanceShape) {
            if (shapes && shapes(info.y, local, traversal.tMax))
                result = RayHit{traversal.tMax, 0.0f, 0.0f, static_cast<std::int32_t>(instance), -1, -1};
            return false;
        }
        const WatertightRay ray = prepareWatertight(local);
        return walkLevel(traversal, info.y, local, [&](glm::uvec4 link) {
            return intersectLeaf(traversal, ray, link, [&](std::uint32_t slot, const TriangleHit& hit) {
                traversal.tMax = hit.t;
                result = RayHit{hit.t, hit.u, hit.v, static_cast<std::int32_t>(instance), static_cast<std::int32_t>(slot),
                                static_cast<std::int32_t>(scene.slotTriangle[slot])};
                return false;
            });
        });
    });
    return result;
}

bool occluded(const FlatScene& scene, const Ray& worldRay, float tMax, const ShapeIntersector& shapes)
{
    bool blocked = false;
    Traversal traversal{scene, tMax};
    walkScene(traversal, worldRay, [&](std::uint32_t, glm::uvec4 info, const Ray& local) {
        if (info.x == kInstanceShape) {
            float limit = traversal.tMax;
            blocked = shapes && shapes(info.y, local, limit);
            return blocked;
        }
        const WatertightRay ray = prepareWatertight(local);
        return walkLevel(traversal, info.y, local, [&](glm::uvec4 link) {
            return intersectLeaf(traversal, ray, link, [&](std::uint32_t, const TriangleHit&) { return blocked = true; });
        });
    });
    return blocked;
}

} // namespace glint::bvh
