// Watertightness (rays through shared edges and vertices of a closed mesh never miss) and robust
// ray offsets (no self-hits, no leaks) at coordinates near 1e5.
#include "bvh_test_scenes.h"
#include "renderer/bvh/ray_offset.h"
#include "renderer/bvh/traverse.h"

#include <glm/gtc/matrix_transform.hpp>

#include <QTest>

#include <limits>

Q_DECLARE_METATYPE(glm::mat4)

using namespace glint;
using namespace glint::bvh;
using namespace glint::bvh::test;

namespace {

constexpr float kFar = std::numeric_limits<float>::max();

// Vertices, edge midpoints and face centres of the grid cube [0, cells]^3 (cell size 1): every
// place where two or more triangles meet, plus interiors for contrast.
std::vector<glm::vec3> sharedFeatures(int cells)
{
    std::vector<glm::vec3> targets;
    for (int x = 0; x <= 2 * cells; ++x)
        for (int y = 0; y <= 2 * cells; ++y)
            for (int z = 0; z <= 2 * cells; ++z) {
                const glm::ivec3 g{x, y, z};
                const bool onSurface = glm::any(glm::equal(g, glm::ivec3(0))) || glm::any(glm::equal(g, glm::ivec3(2 * cells)));
                if (onSurface) targets.push_back(0.5f * glm::vec3(g));
            }
    return targets;
}

// A point from which the ray to `target` crosses into the cube there (not a grazing ray along a
// silhouette edge, which may rightly miss): outside every face plane that holds the target.
glm::vec3 outsideEveryFaceThrough(const glm::vec3& target, int cells, std::mt19937& rng)
{
    std::uniform_real_distribution<float> away(1.0f, 6.0f);
    std::uniform_real_distribution<float> across(-6.0f, cells + 6.0f);
    glm::vec3 origin;
    for (int axis = 0; axis < 3; ++axis) {
        if (target[axis] == 0.0f) origin[axis] = -away(rng);
        else if (target[axis] == static_cast<float>(cells)) origin[axis] = cells + away(rng);
        else origin[axis] = across(rng);
    }
    return origin;
}

glm::vec3 faceNormal(const FlatScene& scene, int slot)
{
    const auto p = [&](int k) { return glm::vec3(scene.trianglePositions[3 * static_cast<std::size_t>(slot) + k]); };
    return glm::normalize(glm::cross(p(1) - p(0), p(2) - p(0)));
}

// A hit within a few float steps (8 mm at 1e5) of an edge of the 16 m room lies on two walls at once:
// no offset along one wall's normal keeps it off the other, so such hits are left out.
bool onTwoWalls(const glm::vec3& localPoint, const glm::vec3& localNormal)
{
    for (int axis = 0; axis < 3; ++axis)
        if (std::abs(localNormal[axis]) < 0.5f && 8.0f - std::abs(localPoint[axis]) < 0.05f) return true;
    return false;
}

glm::vec3 randomDirection(std::mt19937& rng)
{
    std::normal_distribution<float> gauss;
    return glm::normalize(glm::vec3(gauss(rng), gauss(rng), gauss(rng)));
}

glm::vec3 randomHemisphere(std::mt19937& rng, const glm::vec3& n)
{
    std::normal_distribution<float> gauss;
    for (;;) {
        const glm::vec3 d{gauss(rng), gauss(rng), gauss(rng)};
        const float along = glm::dot(d, n);
        if (along > 0.05f * glm::length(d)) return glm::normalize(d);
    }
}

} // namespace

class TestBvhWatertight : public QObject {
    Q_OBJECT
private slots:
    void raysThroughSharedEdgesAndVerticesNeverMiss_data()
    {
        QTest::addColumn<glm::mat4>("worldFromLocal");
        QTest::newRow("identity") << glm::mat4(1.0f);
        QTest::newRow("rotated") << glm::rotate(glm::mat4(1.0f), 0.61f, glm::normalize(glm::vec3(1.0f, 0.3f, -0.7f)));
        QTest::newRow("mirrored, far away") << glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(3e4f, -2e4f, 1e4f)), glm::vec3(-1.5f, 1.0f, 2.0f));
    }

    void raysThroughSharedEdgesAndVerticesNeverMiss()
    {
        QFETCH(glm::mat4, worldFromLocal);
        constexpr int cells = 4;
        const TestScene scene = makeScene({closedGridCube(cells, 1.0f, glm::vec3(0.0f))}, {{0, worldFromLocal}});
        const auto world = [&](glm::vec3 p) { return glm::vec3(worldFromLocal * glm::vec4(p, 1.0f)); };
        const glm::vec3 inside = world(glm::vec3(1.37f, 2.11f, 1.73f));
        std::mt19937 rng(7u);
        int rays = 0;
        for (const glm::vec3& target : sharedFeatures(cells)) {
            // From inside, every ray leaves through the surface.
            const Ray fromInside{inside, world(target) - inside};
            QVERIFY2(intersectClosest(scene.flat, fromInside, kFar).hit(), qPrintable(QString("inside ray to (%1, %2, %3) missed")
                                                                                     .arg(target.x).arg(target.y).arg(target.z)));
            // From outside, a ray that enters the solid through a surface point hits no later than it.
            const glm::vec3 outside = outsideEveryFaceThrough(target, cells, rng);
            const Ray fromOutside{world(outside), world(target) - world(outside)};
            const RayHit hit = intersectClosest(scene.flat, fromOutside, kFar);
            QVERIFY2(hit.hit(), qPrintable(QString("outside ray to (%1, %2, %3) missed").arg(target.x).arg(target.y).arg(target.z)));
            QVERIFY(hit.t <= 1.0f + 1e-3f); // the world-space target itself is rounded (far away: 2 mm steps)
            rays += 2;
        }
        QCOMPARE(rays, 2 * (9 * 9 * 9 - 7 * 7 * 7)); // the lattice's surface points, two rays each
    }

    void offsetRaysNeitherSelfHitNorLeakNear1e5_data()
    {
        QTest::addColumn<glm::mat4>("worldFromLocal");
        QTest::newRow("axis-aligned") << glm::translate(glm::mat4(1.0f), glm::vec3(1e5f, -1e5f, 1e5f));
        QTest::newRow("rotated") << glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(-1e5f, 1e5f, 1e5f)), 0.83f,
                                                glm::normalize(glm::vec3(0.2f, 1.0f, -0.4f)));
    }

    // A 16 m room centred near 1e5, where one float step is 8 mm. From random points inside, hit a
    // wall, take the hit point from the barycentrics (as a renderer does), offset it and shoot on:
    // inwards the ray must hit another wall (no acne, no leak), outwards it must hit nothing.
    void offsetRaysNeitherSelfHitNorLeakNear1e5()
    {
        QFETCH(glm::mat4, worldFromLocal);
        const TestScene scene = makeScene({closedGridCube(8, 2.0f, glm::vec3(-8.0f))}, {{0, worldFromLocal}});
        const auto world = [&](glm::vec3 p) { return glm::vec3(worldFromLocal * glm::vec4(p, 1.0f)); };
        const glm::mat3 normalToWorld = glm::mat3(worldFromLocal);
        std::mt19937 rng(2024u);
        std::uniform_real_distribution<float> inRoom(-7.0f, 7.0f);
        int naiveSelfHits = 0;
        int onEdges = 0;
        constexpr int kRays = 2000;
        for (int i = 0; i < kRays; ++i) {
            const glm::vec3 start = world(glm::vec3(inRoom(rng), inRoom(rng), inRoom(rng)));
            const RayHit wall = intersectClosest(scene.flat, Ray{start, randomDirection(rng)}, kFar);
            QVERIFY(wall.hit());
            const auto p = [&](int k) { return glm::vec3(scene.flat.trianglePositions[3 * static_cast<std::size_t>(wall.slot) + k]); };
            const glm::vec3 localPoint = (1.0f - wall.u - wall.v) * p(0) + wall.u * p(1) + wall.v * p(2);
            const glm::vec3 localNormal = faceNormal(scene.flat, wall.slot);
            if (onTwoWalls(localPoint, localNormal)) {
                ++onEdges;
                continue;
            }
            const glm::vec3 hitPoint = world(localPoint);
            const glm::vec3 n = glm::normalize(normalToWorld * localNormal); // outwards

            const glm::vec3 inward = randomHemisphere(rng, -n);
            const RayHit next = intersectClosest(scene.flat, Ray{offsetRayOrigin(hitPoint, -n), inward}, kFar);
            QVERIFY2(next.hit(), qPrintable(QString("ray %1 leaked out of the room").arg(i)));
            QVERIFY2(glm::dot(faceNormal(scene.flat, next.slot), localNormal) < 0.5f,
                     qPrintable(QString("ray %1 hit its own wall again at t = %2").arg(i).arg(next.t)));
            QVERIFY2(!occluded(scene.flat, Ray{offsetRayOrigin(hitPoint, n), randomHemisphere(rng, n)}, kFar),
                     qPrintable(QString("ray %1 leaving the room hit its own wall").arg(i)));

            const RayHit naive = intersectClosest(scene.flat, Ray{hitPoint, inward}, kFar);
            if (!naive.hit() || glm::dot(faceNormal(scene.flat, naive.slot), localNormal) > 0.5f) ++naiveSelfHits;
        }
        qInfo("%d of %d hits on an edge left out; without the offset %d inward rays would have hit their own wall or leaked",
              onEdges, kRays, naiveSelfHits);
        QVERIFY(onEdges < kRays / 50);
    }
};

QTEST_APPLESS_MAIN(TestBvhWatertight)
#include "test_bvh_watertight.moc"
