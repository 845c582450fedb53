// The viewport camera's navigation math: orbit, pan, zoom, fly, framing, looking through a
// camera and turning the view into a camera-path key. No window, no GL.
#include "editor/viewport/view_camera.h"

#include <QtTest>

#include <glm/gtc/matrix_transform.hpp>

using namespace glint;
using namespace glint::editor;

namespace {

constexpr double kTol = 1e-9;

bool near(const glm::dvec3& a, const glm::dvec3& b, double tol) { return glm::length(a - b) <= tol; }

} // namespace

class TestViewportCamera : public QObject {
    Q_OBJECT
private slots:
    void defaultLooksAlongMinusZ() {
        ViewCamera c;
        QVERIFY(near(c.forward(), {0, 0, -1}, kTol));
        QVERIFY(near(c.position(), {0, 0, 5}, kTol));
        QVERIFY(near(c.up(), {0, 1, 0}, kTol));
        // The orientation maps the camera's -Z to the forward vector (glTF convention).
        QVERIFY(near(c.orientation() * glm::dvec3(0, 0, -1), c.forward(), kTol));
    }

    void orbitKeepsTargetAndDistance() {
        ViewCamera c;
        c.target = {1, 2, 3};
        orbit(c, 120, -40);
        QVERIFY(near(c.target, {1, 2, 3}, kTol));
        QVERIFY(std::abs(glm::length(c.position() - c.target) - 5.0) < 1e-9);
        // Looking at the target from wherever it went.
        QVERIFY(near(c.position() + c.distance * c.forward(), c.target, 1e-9));
    }

    void pitchIsClampedBeforeThePole() {
        ViewCamera c;
        orbit(c, 0, 1e6);
        QVERIFY(c.pitch < 1.5708 && c.pitch > 1.55);
        QVERIFY(std::isfinite(c.right().x));
    }

    void panFollowsTheMouseAtTargetDepth() {
        ViewCamera c;
        const int w = 200, h = 100;
        const glm::dvec3 before = projectToPixels(c, c.target, w, h);
        const glm::dvec3 point = c.target;
        pan(c, 30, -10, h);
        // The world point that was under the cursor moved with it by (30, -10) pixels.
        const glm::dvec3 after = projectToPixels(c, point, w, h);
        QVERIFY(std::abs(after.x - (before.x + 30)) < 1e-6);
        QVERIFY(std::abs(after.y - (before.y - 10)) < 1e-6);
    }

    void zoomScalesDistanceAndStaysPositive() {
        ViewCamera c;
        zoom(c, 1);
        QVERIFY(std::abs(c.distance - 5.0 * 0.85) < kTol);
        zoom(c, -1);
        QVERIFY(std::abs(c.distance - 5.0) < 1e-12);
        zoom(c, 1e4);
        QVERIFY(c.distance > 0.0);
    }

    void lookKeepsThePosition() {
        ViewCamera c;
        c.yaw = 0.3;
        const glm::dvec3 eye = c.position();
        look(c, 50, 20);
        QVERIFY(near(c.position(), eye, 1e-9));
        QVERIFY(std::abs(c.yaw - 0.3) > 0.1);
    }

    void flyMovesInTheCameraFrame() {
        ViewCamera c;
        c.yaw = 0.5;
        const glm::dvec3 eye = c.position();
        fly(c, {0, 0, 2});
        QVERIFY(near(c.position(), eye + 2.0 * c.forward(), 1e-9));
        fly(c, {1, 0, 0});
        QVERIFY(near(c.position(), eye + 2.0 * c.forward() + c.right(), 1e-9));
    }

    void frameSphereFitsTheView() {
        ViewCamera c;
        frameSphere(c, {3, 0, 0}, 2.0, 16.0 / 9.0);
        QVERIFY(near(c.target, {3, 0, 0}, kTol));
        // The sphere's silhouette is inside the vertical field of view with a margin.
        const double halfAngle = std::asin(2.0 / c.distance);
        QVERIFY(halfAngle < 0.5 * c.yfov);
        QVERIFY(halfAngle > 0.8 * 0.5 * c.yfov);
    }

    void setFromWorldRoundTrips() {
        ViewCamera a;
        a.target = {1, -2, 0.5};
        a.yaw = -2.1;
        a.pitch = 0.4;
        ViewCamera b;
        setFromWorld(b, a.worldFromCamera(), 0.9f);
        QVERIFY(near(b.position(), a.position(), 1e-5));
        QVERIFY(near(b.forward(), a.forward(), 1e-6));
        QCOMPARE(b.yfov, 0.9f);
    }

    void keyFromViewHoldsThePose() {
        ViewCamera c;
        c.yaw = 1.0;
        c.pitch = -0.2;
        const CameraKey key = keyFromView(c, 2.5);
        QCOMPARE(key.time, 2.5);
        QVERIFY(near(key.position, c.position(), kTol));
        QVERIFY(near(key.orientation * glm::dvec3(0, 0, -1), c.forward(), 1e-12));
        QCOMPARE(key.yfov, c.yfov);
    }

    void pixelRayAndProjectionAgree() {
        ViewCamera c;
        c.yaw = 0.7;
        c.pitch = 0.3;
        const int w = 160, h = 90;
        const bvh::Ray ray = pixelRay(c, 40.5, 70.5, w, h);
        const glm::dvec3 p = glm::dvec3(ray.origin) + 7.0 * glm::dvec3(ray.direction);
        const glm::dvec3 px = projectToPixels(c, p, w, h);
        QVERIFY(std::abs(px.x - 40.5) < 1e-3);
        QVERIFY(std::abs(px.y - 70.5) < 1e-3);
        QVERIFY(px.z > 0);
        // The centre pixel ray is the forward vector.
        const bvh::Ray centre = pixelRay(c, 80, 45, w, h);
        QVERIFY(near(glm::dvec3(centre.direction), c.forward(), 1e-6));
    }

    void clipFromWorldMatchesProjection() {
        ViewCamera c;
        c.yaw = -0.4;
        const int w = 200, h = 100;
        const glm::dvec3 p(0.3, 0.2, -1.0);
        const glm::vec4 clip = clipFromWorld(c, double(w) / h) * glm::vec4(glm::vec3(p), 1.0f);
        const double x = (clip.x / clip.w + 1.0) * 0.5 * w;
        const double y = (1.0 - clip.y / clip.w) * 0.5 * h;
        const glm::dvec3 px = projectToPixels(c, p, w, h);
        QVERIFY(std::abs(x - px.x) < 1e-3);
        QVERIFY(std::abs(y - px.y) < 1e-3);
    }
};

QTEST_APPLESS_MAIN(TestViewportCamera)
#include "test_viewport_camera.moc"
