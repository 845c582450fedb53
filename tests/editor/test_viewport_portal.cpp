// The view camera flying through a linked portal: a fly step whose eye crosses portal A comes out
// of portal B, the eye as far beyond B as it went past A, the view direction turned as the pair
// turns, the orbit target carried along. Steps beside the rectangle, through an unlinked quad, or
// on out of the exit do nothing. No window, no GL.
#include "editor/viewport/portal_travel.h"

#include <QtTest>

#include <glm/gtc/quaternion.hpp>

#include <numbers>

using namespace glint;
using namespace glint::editor;

namespace {

constexpr double kTol = 1e-5;
constexpr float kQuarter = 0.5f * std::numbers::pi_v<float>;

bool near(const glm::dvec3& a, const glm::dvec3& b) { return glm::length(a - b) <= kTol; }

// A 2 m quad at `at` whose normal (+Y) is turned to +Z, then by `yaw` about +Y.
NodeId addPortal(Scene& scene, glm::vec3 at, float yaw) {
    Node node;
    node.local.translation = at;
    node.local.rotation = glm::angleAxis(yaw, glm::vec3(0, 1, 0)) * glm::angleAxis(kQuarter, glm::vec3(1, 0, 0));
    Shape quad;
    quad.kind = ShapeKind::Quad;
    quad.size = {2.0f, 1.0f, 2.0f};
    node.component = quad;
    return scene.addNode(std::move(node));
}

void link(Scene& scene, NodeId from, NodeId to) {
    Shape shape = *scene.at(from).get<Shape>();
    shape.portal = to;
    scene.setComponent(from, shape);
}

// A at (0, 1, 0) facing +Z; B at (10, 1, 0) facing +X.
Scene pair() {
    Scene scene;
    const NodeId a = addPortal(scene, {0, 1, 0}, 0.0f);
    const NodeId b = addPortal(scene, {10, 1, 0}, kQuarter);
    link(scene, a, b);
    link(scene, b, a);
    return scene;
}

// Eye at (x, 1, 1) looking along -Z at a target 5 m ahead, towards A's front.
ViewCamera facingA(double x = 0.0) {
    ViewCamera camera;
    camera.target = {x, 1.0, -4.0};
    camera.distance = 5.0;
    return camera;
}

// One fly step forward, as the viewport's fly tool makes it.
bool flyForward(ViewCamera& camera, const Scene& scene, double metres) {
    const glm::dvec3 before = camera.position();
    fly(camera, {0.0, 0.0, metres});
    return carryThroughPortal(camera, scene, before);
}

} // namespace

class TestViewportPortal : public QObject {
    Q_OBJECT
private slots:
    // 2 m forward from 1 m in front of A: 1 m past A's plane, so 1 m out of B's front along +X.
    void flyStepThroughAComesOutOfB() {
        const Scene scene = pair();
        ViewCamera camera = facingA();
        QVERIFY(flyForward(camera, scene, 2.0));
        QVERIFY(near(camera.position(), {11, 1, 0}));
        QVERIFY(near(camera.forward(), {1, 0, 0}));
        QVERIFY(near(camera.up(), {0, 1, 0}));
        QVERIFY(std::abs(camera.distance - 5.0) < kTol);
        QVERIFY(near(camera.target, {16, 1, 0})); // the target, 5 m ahead past A, is 5 m ahead past B
        // Flying on out of B stays on this side.
        QVERIFY(!flyForward(camera, scene, 2.0));
        QVERIFY(near(camera.position(), {13, 1, 0}));
    }

    // Into B's front (against +X), 0.5 m past it, is 0.5 m out of A's front along +Z: both ways.
    void flyBackThroughB() {
        const Scene scene = pair();
        ViewCamera camera;
        camera.yaw = 0.5 * std::numbers::pi; // looking along -X, 1.5 m in front of B
        camera.target = glm::dvec3(11.5, 1, 0) + 5.0 * camera.forward();
        QVERIFY(near(camera.forward(), {-1, 0, 0}));
        QVERIFY(flyForward(camera, scene, 2.0));
        QVERIFY(near(camera.position(), {0, 1, 0.5}));
        QVERIFY(near(camera.forward(), {0, 0, 1}));
    }

    void missingTheRectangleDoesNothing() {
        const Scene scene = pair();
        ViewCamera camera = facingA(1.5); // 0.5 m beside A's 2 m width
        QVERIFY(!flyForward(camera, scene, 2.0));
        QVERIFY(near(camera.position(), {1.5, 1, -1}));
    }

    void unlinkedQuadIsAWall() {
        Scene scene = pair();
        link(scene, NodeId{2}, NodeId{}); // B no longer names A: A is an ordinary quad
        ViewCamera camera = facingA();
        QVERIFY(!flyForward(camera, scene, 2.0));
        QVERIFY(near(camera.position(), {0, 1, -1}));
    }

    // Zooming (the eye moves towards the target) through A carries the eye and target alike.
    void zoomThroughA() {
        const Scene scene = pair();
        ViewCamera camera = facingA();
        const glm::dvec3 before = camera.position();
        zoom(camera, 10.0); // 5 m x 0.85^10 = 0.98 m from the target: 3.03 m past A
        QVERIFY(carryThroughPortal(camera, scene, before));
        const double past = 4.0 - 5.0 * std::pow(0.85, 10.0);
        QVERIFY(near(camera.position(), {10.0 + past, 1, 0}));
        QVERIFY(near(camera.target, {14, 1, 0}));
    }
};

QTEST_APPLESS_MAIN(TestViewportPortal)
#include "test_viewport_portal.moc"
