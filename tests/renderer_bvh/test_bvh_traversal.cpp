// CPU traversal of the flattened two-level BVH against brute force over every triangle: the same
// closest t (bit for bit) and the same triangle, on the bunny and on transformed instances.
#include "bvh_test_scenes.h"
#include "renderer/bvh/traverse.h"
#include "renderer/bvh/bvh_layout.h"
#include "renderer/bvh/triangle_intersect.h"
#include "renderer/bvh/validate.h"

#include <glm/gtc/matrix_transform.hpp>

#include <QTest>

#include <cmath>
#include <limits>

using namespace glint;
using namespace glint::bvh;
using namespace glint::bvh::test;

namespace {

constexpr float kFar = std::numeric_limits<float>::max();

Aabb sceneBounds(const TestScene& scene)
{
    Aabb bounds;
    for (const Aabb& box : scene.topLevel.worldBounds) bounds.grow(box);
    return bounds;
}

// Two triangles at exactly the same t (a ray through a shared edge) are both right answers.
bool sameTriangleOrTie(const RayHit& bvh, const RayHit& brute)
{
    if (bvh.instance == brute.instance && bvh.triangle == brute.triangle) return true;
    return bvh.t == brute.t;
}

struct Agreement {
    int rays = 0;
    int hits = 0;
    int ties = 0;
};

void compareRandomRays(const TestScene& scene, int rayCount, std::uint32_t seed, Agreement& agreement)
{
    std::mt19937 rng(seed);
    const Aabb bounds = sceneBounds(scene);
    for (int i = 0; i < rayCount; ++i) {
        const Ray ray = randomRayThrough(rng, bounds);
        const RayHit brute = bruteForceClosest(scene, ray, kFar);
        const RayHit bvh = intersectClosest(scene.flat, ray, kFar);
        QCOMPARE(bvh.hit(), brute.hit());
        QCOMPARE(occluded(scene.flat, ray, kFar), brute.hit());
        ++agreement.rays;
        if (!brute.hit()) continue;
        ++agreement.hits;
        QCOMPARE(bvh.t, brute.t);
        QVERIFY2(sameTriangleOrTie(bvh, brute), qPrintable(QString("ray %1: triangle %2 vs %3").arg(i).arg(bvh.triangle).arg(brute.triangle)));
        if (bvh.triangle != brute.triangle) ++agreement.ties;
        QCOMPARE(scene.flat.slotTriangle[static_cast<std::size_t>(bvh.slot)], static_cast<std::uint32_t>(bvh.triangle));
        // Shadow rays stop just short of the hit and find nothing closer.
        QCOMPARE(occluded(scene.flat, ray, brute.t), false);
    }
}

} // namespace

class TestBvhTraversal : public QObject {
    Q_OBJECT
private slots:
    void bunnyRandomRaysMatchBruteForce()
    {
        const TestScene scene = makeScene({loadBunny()}, {{0, glm::mat4(1.0f)}});
        Agreement agreement;
        compareRandomRays(scene, 2000, 1234u, agreement);
        qInfo("bunny: %d rays, %d hits, %d exact ties", agreement.rays, agreement.hits, agreement.ties);
        QVERIFY(agreement.hits > 800); // most rays aim at the bunny's box; a good share must hit it
    }

    void transformedInstancesMatchBruteForce()
    {
        glm::mat4 rotated = glm::translate(glm::mat4(1.0f), glm::vec3(0.3f, 0.0f, 0.0f));
        rotated = glm::rotate(rotated, 0.7f, glm::normalize(glm::vec3(1.0f, 2.0f, 0.5f)));
        const glm::mat4 stretched = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(-0.3f, 0.1f, 0.0f)), glm::vec3(2.0f, 0.5f, 1.0f));
        const glm::mat4 mirrored = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, 0.25f)), glm::vec3(-1.0f, 1.0f, 1.0f));
        const glm::mat4 cube = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -0.2f, 0.0f)), 0.3f, glm::vec3(0, 1, 0));
        const TestScene scene = makeScene({loadBunny(), closedGridCube(6, 0.05f, glm::vec3(-0.15f))},
                                          {{0, rotated}, {0, stretched}, {0, mirrored}, {1, cube}});
        QCOMPARE(scene.topLevel.instances.size(), std::size_t{4});
        QCOMPARE(validateFlatScene(scene.flat), std::optional<std::string>{});
        QCOMPARE(scene.flat.instances[4 * 2 + 3].w, 1u); // the mirrored instance is flagged
        Agreement agreement;
        compareRandomRays(scene, 600, 99u, agreement);
        qInfo("instances: %d rays, %d hits, %d exact ties", agreement.rays, agreement.hits, agreement.ties);
        QVERIFY(agreement.hits > 200);
    }

    void nanAndZeroRaysEndWithoutAHit()
    {
        const TestScene scene = makeScene({loadBunny()}, {{0, glm::mat4(1.0f)}});
        const float nan = std::numeric_limits<float>::quiet_NaN();
        QVERIFY(!intersectClosest(scene.flat, Ray{{nan, 0.1f, 0.0f}, {0, 0, 1}}, kFar).hit());
        QVERIFY(!intersectClosest(scene.flat, Ray{{0.0f, 0.1f, -1.0f}, {nan, nan, nan}}, kFar).hit());
        QVERIFY(!intersectClosest(scene.flat, Ray{{0.0f, 0.1f, -1.0f}, {0, 0, 0}}, kFar).hit());
        QVERIFY(!occluded(scene.flat, Ray{{0.0f, 0.1f, -1.0f}, {nan, 0, 1}}, kFar));
    }

    void aCycleInCorruptBuffersStillEnds()
    {
        TestScene scene = makeScene({loadBunny()}, {{0, glm::mat4(1.0f)}});
        // Every interior node points back at the root's children: validation refuses this; the
        // traversal still stops after kMaxTraversalSteps nodes.
        const std::uint32_t rootChildren = nodeLink(scene.flat, 0).x;
        for (std::uint32_t n = 1; n < scene.flat.meshNodeCount; ++n)
            if (nodeLink(scene.flat, n).y == 0) setLink(scene.flat, n, rootChildren, 0);
        QVERIFY(validateFlatScene(scene.flat).has_value());
        const Ray ray{{-0.02f, 0.1f, -1.0f}, {0.0f, 0.0f, 1.0f}};
        (void)intersectClosest(scene.flat, ray, kFar);
        (void)occluded(scene.flat, ray, kFar); // returning at all is what this test is about
    }

    void shapeInstancesGoThroughTheIntersector()
    {
        // A unit sphere (shape 7 of the renderer's table) at z = 5 in front of a cube at z = 10.
        const std::vector<MeshBvh> meshes{buildMeshBvh(closedGridCube(2, 1.0f, glm::vec3(-1.0f)), BuildOptions{})};
        const std::vector<Instance> instances{
            {glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 10)), kInstanceMesh, 0, 1, {}},
            {glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 5)), glm::vec3(2.0f)), kInstanceShape, 7, 2,
             Aabb{glm::vec3(-1.0f), glm::vec3(1.0f)}}};
        const FlatScene flat = flattenScene(meshes, buildTopLevel(instances, meshes));
        QCOMPARE(validateFlatScene(flat), std::optional<std::string>{});
        std::vector<std::uint32_t> asked;
        const ShapeIntersector unitSphere = [&](std::uint32_t shape, const Ray& local, float& tMax) {
            asked.push_back(shape);
            const float a = glm::dot(local.direction, local.direction);
            const float b = glm::dot(local.origin, local.direction);
            const float c = glm::dot(local.origin, local.origin) - 1.0f;
            const float disc = b * b - a * c;
            if (disc < 0.0f) return false;
            const float t = (-b - std::sqrt(disc)) / a;
            if (!(t > 0.0f && t < tMax)) return false;
            tMax = t;
            return true;
        };
        const Ray ray{{0.5f, 0.5f, 0.0f}, {0.0f, 0.0f, 1.0f}};
        const RayHit hit = intersectClosest(flat, ray, kFar, unitSphere);
        QCOMPARE(hit.instance, 1);
        QCOMPARE(hit.slot, -1);
        QCOMPARE(hit.t, 5.0f - std::sqrt(4.0f - 0.5f)); // the sphere of radius 2 at z = 5
        QCOMPARE(asked, std::vector<std::uint32_t>{7});
        QVERIFY(occluded(flat, ray, 4.0f, unitSphere));
        QVERIFY(!occluded(flat, ray, 3.0f, unitSphere));
        // Without an intersector the shape is skipped and the cube behind it is hit.
        const RayHit behind = intersectClosest(flat, ray, kFar);
        QCOMPARE(behind.instance, 0);
        QCOMPARE(behind.t, 9.0f);
    }

    void closestHitReportsBarycentrics()
    {
        MeshTriangles one;
        one.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
        one.triangles = {{0, 1, 2}};
        one.materials = {5};
        one.primitiveOf = {0};
        const TestScene scene = makeScene({one}, {{0, glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 2))}});
        const RayHit hit = intersectClosest(scene.flat, Ray{{0.25f, 0.5f, 0.0f}, {0.0f, 0.0f, 2.0f}}, kFar);
        QCOMPARE(hit.t, 1.0f); // direction length 2: t is in its units
        QCOMPARE(hit.u, 0.25f);
        QCOMPARE(hit.v, 0.5f);
        QCOMPARE(scene.flat.triangleVertices[static_cast<std::size_t>(hit.slot)].w, 5u);
        QVERIFY(!intersectClosest(scene.flat, Ray{{0.25f, 0.5f, 0.0f}, {0.0f, 0.0f, 2.0f}}, 1.0f).hit());
    }
};

QTEST_APPLESS_MAIN(TestBvhTraversal)
#include "test_bvh_traversal.moc"
