// Paired portals (scene/core/portal.h, docs/PORTALS.md): the view through a portal equals the
// render from the camera carried through the pair's map, pixel for pixel up to float rounding; a
// chain of facing portals stops after the bounce limit + 1 crossings and then shows the portal
// quad's own surface; a link that is not a pair changes nothing. Scenes are built in code.
#include "image_stats.h"
#include "render_scene.h"
#include "scene_builder.h"

#include "renderer/gpu_scene/packed_scene.h"
#include "renderer/offline_render.h"
#include "scene/core/portal.h"

#include <QTest>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <memory>

using namespace glint;
using namespace glint::test;

namespace {

void link(Scene& scene, NodeId a, NodeId b) {
    std::get<Shape>(scene.component(a)).portal = b;
    std::get<Shape>(scene.component(b)).portal = a;
}

Transform transformOf(const glm::mat4& worldFromLocal) {
    Transform t;
    t.translation = glm::vec3(worldFromLocal[3]);
    t.rotation = glm::normalize(glm::quat_cast(glm::mat3(worldFromLocal)));
    return t;
}

// Everything the camera sees lies above the plane y = 0 (a red ball, a grey box, a white back
// wall, a small emitting ball): light paths between them never meet that plane, so a portal
// lying in it only changes what crosses it from below. The environment is black.
Scene roomAbovePlane() {
    Scene scene;
    const MaterialId red = scene.materials.add(lambert({0.8f, 0.2f, 0.1f}));
    const MaterialId grey = scene.materials.add(lambert(glm::vec3(0.5f)));
    const MaterialId lamp = scene.materials.add(lambert(glm::vec3(0.0f), glm::vec3(40.0f)));
    addShape(scene, ShapeKind::Sphere, red, {0.0f, 2.0f, 0.0f}, 0.8f);
    addShape(scene, ShapeKind::Box, grey, {1.4f, 1.5f, -0.9f}, 0.5f, glm::vec3(1.0f, 1.2f, 0.8f));
    addShape(scene, ShapeKind::Quad, grey, {0.0f, 6.0f, 0.0f}, 0.5f, glm::vec3(8.0f, 1.0f, 8.0f),
             glm::angleAxis(glm::pi<float>(), glm::vec3(1.0f, 0.0f, 0.0f))); // facing down
    addShape(scene, ShapeKind::Sphere, lamp, {-1.5f, 3.5f, 1.0f}, 0.3f);
    return scene;
}

} // namespace

class TestRenderPortals : public QObject {
    Q_OBJECT
    std::unique_ptr<renderer::OfflineRenderer> renderer_;

    renderer::RenderOutput render(const Scene& scene, int size, int spp, int bounces, const std::string& camera) {
        renderer::RenderRequest request = stillRequest(size, spp, 7, bounces);
        request.tonemapper = Tonemapper::None;
        request.cameraName = camera;
        return renderer_->render(scene, request);
    }

private slots:
    void initTestCase() { renderer_ = std::make_unique<renderer::OfflineRenderer>(); }

    void mapIsHalfATurnAndNeverMirrors() {
        Scene scene;
        const NodeId a = addShape(scene, ShapeKind::Quad, MaterialId{}, {3.0f, 0.0f, 0.0f}, 0.5f, glm::vec3(2.0f, 1.0f, 2.0f));
        const NodeId b = addShape(scene, ShapeKind::Quad, MaterialId{}, {0.0f, 0.0f, 5.0f}, 0.5f, glm::vec3(2.0f, 1.0f, 2.0f));
        QVERIFY(!portalPartner(scene, a)); // not linked yet
        std::get<Shape>(scene.component(a)).portal = b;
        QVERIFY(!portalPartner(scene, a)); // one-sided: no pair
        link(scene, a, b);
        QCOMPARE(*portalPartner(scene, a), b);
        const glm::mat4 map = portalWorldFromWorld(scene, a, b);
        QVERIFY(glm::determinant(glm::mat3(map)) > 0.99f);
        // Entering a's front (+Y) straight down, 0.5 m right of its centre: out of b's front, going up,
        // 0.5 m to the left (half a turn about Z), at b's centre height.
        const glm::vec3 exit(map * glm::vec4(3.5f, 0.0f, 0.0f, 1.0f));
        const glm::vec3 direction(map * glm::vec4(0.0f, -1.0f, 0.0f, 0.0f));
        QVERIFY(glm::length(exit - glm::vec3(-0.5f, 0.0f, 5.0f)) < 1e-5f);
        QVERIFY(glm::length(direction - glm::vec3(0.0f, 1.0f, 0.0f)) < 1e-6f);
        const auto crossing = firstPortalCrossing(scene, {3.2f, 1.0f, 0.3f}, {3.2f, -1.0f, 0.3f});
        QVERIFY(crossing && crossing->entry == a && crossing->exit == b);
        QVERIFY(std::abs(crossing->t - 0.5f) < 1e-6f);
        QVERIFY(!firstPortalCrossing(scene, {5.0f, 1.0f, 0.0f}, {5.0f, -1.0f, 0.0f})); // beside the quad
    }

    void pairsArePackedAndNeverLightSampled() {
        Scene scene;
        const MaterialId glowing = scene.materials.add(lambert(glm::vec3(0.5f), glm::vec3(2.0f)));
        const NodeId a = addShape(scene, ShapeKind::Quad, glowing, {0.0f, 0.0f, 0.0f});
        addShape(scene, ShapeKind::Sphere, glowing, {0.0f, 3.0f, 0.0f});
        const NodeId b = addShape(scene, ShapeKind::Quad, glowing, {4.0f, 0.0f, 0.0f});
        renderer::PackedScene unlinked = renderer::packScene(scene);
        QVERIFY(!unlinked.portals);
        link(scene, a, b);
        const renderer::PackedScene packed = renderer::packScene(scene);
        QVERIFY(packed.portals);
        const auto texel = [&](int shape, int i) { return packed.shapes[std::size_t(shape * renderer::shapeTexels + i)]; };
        QCOMPARE(texel(0, 5).z, 3.0f); // a's partner: shape 2
        QCOMPARE(texel(2, 5).z, 1.0f);
        QCOMPARE(texel(1, 5).z, 0.0f);
        QCOMPARE(texel(0, 5).x, 0.0f); // a portal emits no power to sample
        QCOMPARE(packed.shapeEmitterPower, texel(1, 5).x);
        QVERIFY(packed.shapeEmitterPower > 0.0f);
    }

    // Camera C looks at portal A from below; A's partner B lies in the plane y = 0 under the room.
    // The reference renders the room without portals from C carried through the map. Both images
    // trace the same paths from B's plane on, with the same random numbers (a crossing draws none).
    void viewThroughPortalEqualsMappedCamera() {
        const int size = 64, spp = 16, bounces = 3;
        Scene reference = roomAbovePlane();
        Scene portals = roomAbovePlane();
        const MaterialId frame = portals.materials.add(lambert(glm::vec3(0.3f)));
        const glm::quat aRotation = glm::angleAxis(glm::pi<float>(), glm::vec3(1.0f, 0.0f, 0.0f)) *
                                    glm::angleAxis(0.7f, glm::vec3(0.0f, 1.0f, 0.0f)); // facing down, turned
        const glm::vec3 big(200.0f, 1.0f, 200.0f);
        const NodeId a = addShape(portals, ShapeKind::Quad, frame, {2.0f, -50.0f, 1.0f}, 0.5f, big, aRotation);
        const NodeId b = addShape(portals, ShapeKind::Quad, frame, glm::vec3(0.0f), 0.5f, big);
        link(portals, a, b);
        // C: 6 m in front of A, looking at it slightly off its normal.
        const glm::mat4 worldFromA = portals.worldFromNode(a);
        const glm::vec3 eye(worldFromA * glm::vec4(0.4f, 6.0f, -0.3f, 1.0f));
        const glm::vec3 forward = glm::normalize(glm::vec3(worldFromA * glm::vec4(0.1f, -1.0f, 0.15f, 0.0f)));
        Camera lens;
        lens.yfov = 1.0f;
        const NodeId camera = addNode(portals, "through", lens, eye, lookRotation(forward, glm::vec3(0.0f, 0.0f, 1.0f)));
        const glm::mat4 mapped = portalWorldFromWorld(portals, a, b) * portals.worldFromNode(camera);
        Node carried;
        carried.name = "mapped";
        carried.local = transformOf(mapped);
        carried.component = lens;
        reference.addNode(std::move(carried));

        const renderer::RenderOutput through = render(portals, size, spp, bounces, "through");
        const renderer::RenderOutput expected = render(reference, size, spp, bounces, "mapped");
        const ChannelStats stats = channelStats(expected.radiance, 0);
        QVERIFY2(stats.mean > 0.05 && stats.maximum > 4.0 * stats.mean,
                 qPrintable(QString("reference mean %1, max %2: the room is not in view").arg(stats.mean).arg(stats.maximum)));
        int differing = 0;
        double sumDifference = 0.0, sum = 0.0;
        for (int y = 0; y < size; ++y) {
            for (int x = 0; x < size; ++x) {
                for (int c = 0; c < 3; ++c) {
                    const double want = pixel(expected.radiance, size, x, y, c);
                    const double got = pixel(through.radiance, size, x, y, c);
                    sumDifference += std::abs(got - want);
                    sum += want;
                    if (std::abs(got - want) > 1e-3 * (1.0 + want)) ++differing;
                }
            }
        }
        qInfo("%d of %d values differ; summed difference %g of %g", differing, size * size * 3, sumDifference, sum);
        // Rounding moves hit points by a few ULPs; where that flips a sampled ray past an edge a
        // pixel differs. Allowed: 1 % of the values, and 0.05 % of the image's sum.
        QVERIFY2(differing <= size * size * 3 / 100, qPrintable(QString("%1 values differ").arg(differing)));
        QVERIFY2(sumDifference <= 5e-4 * sum, qPrintable(QString("summed difference %1 of %2").arg(sumDifference).arg(sum)));
    }

    // Portals A (y = 0, facing up) and B (y = 10, facing down) face each other; the camera between
    // them looks down at A. Every crossing carries the ray from B's plane down through a tinted,
    // index-matched sheet (transmission 1, IOR 1, tint 0.5) to A again. After bounces + 1 crossings
    // A is a surface, emitting 1 with a black base: the pixel reads 0.5^(bounces + 1) exactly.
    void chainStopsAtTheBounceLimit() {
        Scene scene;
        const MaterialId glowing = scene.materials.add(lambert(glm::vec3(0.0f), glm::vec3(1.0f)));
        Material tint = glass(1.0f, 0.0f);
        tint.baseColorFactor = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
        const MaterialId sheet = scene.materials.add(tint);
        const glm::vec3 size(4.0f, 1.0f, 4.0f);
        const NodeId a = addShape(scene, ShapeKind::Quad, glowing, glm::vec3(0.0f), 0.5f, size);
        const NodeId b = addShape(scene, ShapeKind::Quad, glowing, {0.0f, 10.0f, 0.0f}, 0.5f, size,
                                  glm::angleAxis(glm::pi<float>(), glm::vec3(1.0f, 0.0f, 0.0f)));
        link(scene, a, b);
        addShape(scene, ShapeKind::Quad, sheet, {0.0f, 7.0f, 0.0f}, 0.5f, glm::vec3(6.0f, 1.0f, 6.0f));
        addOrthographicCamera(scene, {0.0f, 5.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 1.0f);
        for (const int bounces : {0, 2, 4}) {
            const renderer::RenderOutput out = render(scene, 16, 1, bounces, "camera");
            const double expected = std::pow(0.5, bounces + 1);
            const ChannelStats stats = channelStats(out.radiance, 1);
            QVERIFY2(std::abs(stats.minimum - expected) < 1e-5 * expected + 1e-7 &&
                         std::abs(stats.maximum - expected) < 1e-5 * expected + 1e-7,
                     qPrintable(QString("bounces %1: %2..%3, expected %4").arg(bounces).arg(stats.minimum).arg(stats.maximum).arg(expected)));
        }
    }

    // A quad naming another that does not name it back is an ordinary quad: the same pixels.
    void oneSidedLinkChangesNothing() {
        Scene plain = roomAbovePlane();
        const MaterialId grey = plain.materials.add(lambert(glm::vec3(0.5f)));
        const NodeId floor = addShape(plain, ShapeKind::Quad, grey, glm::vec3(0.0f), 0.5f, glm::vec3(6.0f, 1.0f, 6.0f));
        const NodeId other = addShape(plain, ShapeKind::Quad, grey, {0.0f, -3.0f, 0.0f}, 0.5f, glm::vec3(6.0f, 1.0f, 6.0f));
        addPerspectiveCamera(plain, {0.0f, 2.0f, 6.0f}, {0.0f, 1.0f, 0.0f}, 0.8f);
        Scene linked = plain;
        std::get<Shape>(linked.component(floor)).portal = other;
        QVERIFY(!renderer::packScene(linked).portals);
        const renderer::RenderOutput a = render(plain, 32, 4, 2, "camera");
        const renderer::RenderOutput b = render(linked, 32, 4, 2, "camera");
        QVERIFY(a.radiance == b.radiance);
    }
};

QTEST_GUILESS_MAIN(TestRenderPortals)
#include "test_render_portals.moc"
