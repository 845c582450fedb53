// Gizmo math: handle picking, drag amounts with and without snapping, and the local transforms
// the drags produce (also under a rotated, scaled parent). No window, no GL.
#include "editor/viewport/gizmo_math.h"

#include <QtTest>

#include <glm/gtc/matrix_transform.hpp>

#include <numbers>

using namespace glint;
using namespace glint::editor;

namespace {

// A ray from a camera on +Z (at z = 10) through the world point (x, y, 0).
bvh::Ray rayAt(double x, double y) {
    const glm::vec3 eye(0.0f, 0.0f, 10.0f);
    return {eye, glm::vec3(float(x), float(y), 0.0f) - eye};
}

bool near(const glm::vec3& a, const glm::vec3& b, float tol) { return glm::length(a - b) <= tol; }

} // namespace

class TestViewportGizmo : public QObject {
    Q_OBJECT
private slots:
    void snapRoundsToSteps() {
        QCOMPARE(snapValue(0.26, 0.1), 0.30000000000000004);
        QCOMPARE(snapValue(-0.24, 0.1), -0.2);
        QCOMPARE(snapValue(0.26, 0.0), 0.26);
    }

    void picksTheAxisUnderTheRay() {
        GizmoFrame frame;
        QCOMPARE(pickGizmoAxis(rayAt(0.6, 0.0), frame, GizmoMode::Translate), std::optional<int>(0));
        QCOMPARE(pickGizmoAxis(rayAt(0.0, 0.7), frame, GizmoMode::Translate), std::optional<int>(1));
        QCOMPARE(pickGizmoAxis(rayAt(0.6, 0.5), frame, GizmoMode::Translate), std::optional<int>());
        // Rotate: the Z ring (in the XY plane facing the camera) at radius 1.
        QCOMPARE(pickGizmoAxis(rayAt(0.7071, 0.7071), frame, GizmoMode::Rotate), std::optional<int>(2));
        QCOMPARE(pickGizmoAxis(rayAt(0.3, 0.3), frame, GizmoMode::Rotate), std::optional<int>());
    }

    void translateDragFollowsTheAxis() {
        GizmoFrame frame;
        const auto amount = dragAmount(GizmoMode::Translate, frame, 0, rayAt(0.5, 0.0), rayAt(1.75, 0.0), GizmoSnap{});
        QVERIFY(amount);
        QVERIFY(std::abs(*amount - 1.25) < 1e-5);
        GizmoSnap snap{true, 0.5, 15.0, 0.1};
        const auto snapped = dragAmount(GizmoMode::Translate, frame, 0, rayAt(0.5, 0.0), rayAt(1.75, 0.0), snap);
        QVERIFY(std::abs(*snapped - 1.5) < 1e-12);
    }

    void rotateDragMeasuresTheAngle() {
        GizmoFrame frame;
        const auto amount = dragAmount(GizmoMode::Rotate, frame, 2, rayAt(1.0, 0.0), rayAt(1.0, 1.0), GizmoSnap{});
        QVERIFY(std::abs(*amount - std::numbers::pi / 4) < 1e-5);
        GizmoSnap snap{true, 0.1, 40.0, 0.1};
        const auto snapped = dragAmount(GizmoMode::Rotate, frame, 2, rayAt(1.0, 0.0), rayAt(1.0, 1.0), snap);
        QVERIFY(std::abs(*snapped - 2.0 * std::numbers::pi / 9) < 1e-12);
    }

    void scaleDragIsARatio() {
        GizmoFrame frame;
        const auto amount = dragAmount(GizmoMode::Scale, frame, 1, rayAt(0.0, 0.5), rayAt(0.0, 1.0), GizmoSnap{});
        QVERIFY(std::abs(*amount - 2.0) < 1e-5);
    }

    void parallelRayGivesNoDrag() {
        GizmoFrame frame;
        const bvh::Ray alongZ{glm::vec3(0, 0, 10), glm::vec3(0, 0, -1)};
        QVERIFY(!dragAmount(GizmoMode::Translate, frame, 2, alongZ, alongZ, GizmoSnap{}));
    }

    void translateUnderAScaledRotatedParent() {
        const glm::mat4 parent = glm::scale(glm::rotate(glm::mat4(1.0f), 1.0f, glm::vec3(0, 1, 0)), glm::vec3(2.0f));
        Transform local;
        local.translation = {1, 2, 3};
        const Transform moved = applyDrag(GizmoMode::Translate, local, parent, {1, 0, 0}, 0, 3.0);
        const glm::vec3 worldBefore = parent * glm::vec4(local.translation, 1.0f);
        const glm::vec3 worldAfter = parent * glm::vec4(moved.translation, 1.0f);
        QVERIFY(near(worldAfter - worldBefore, {3, 0, 0}, 1e-5f));
        QCOMPARE(moved.rotation, local.rotation);
        QCOMPARE(moved.scale, local.scale);
    }

    void rotateTurnsAboutTheWorldAxis() {
        const glm::mat4 parent = glm::rotate(glm::mat4(1.0f), 0.5f, glm::vec3(1, 0, 0));
        Transform local;
        const Transform turned = applyDrag(GizmoMode::Rotate, local, parent, {0, 1, 0}, 1, std::numbers::pi / 2);
        // The node's local +X ends up on world -Z.
        const glm::vec3 worldX = glm::mat3(parent) * (turned.rotation * glm::vec3(1, 0, 0));
        QVERIFY(near(worldX, {0, 0, -1}, 1e-5f));
        QCOMPARE(turned.translation, local.translation);
    }

    void scaleChangesOneAxis() {
        Transform local;
        local.scale = {1, 2, 3};
        const Transform scaled = applyDrag(GizmoMode::Scale, local, glm::mat4(1.0f), {0, 1, 0}, 1, 1.5);
        QCOMPARE(scaled.scale, glm::vec3(1, 3, 3));
    }

    void zeroDragIsExactlyTheStart() {
        Transform local;
        local.translation = {0.1f, 0.2f, 0.3f};
        local.rotation = glm::normalize(glm::quat(0.9f, 0.1f, 0.2f, 0.3f));
        QCOMPARE(applyDrag(GizmoMode::Translate, local, glm::mat4(1.0f), {1, 0, 0}, 0, 0.0), local);
        QCOMPARE(applyDrag(GizmoMode::Scale, local, glm::mat4(1.0f), {1, 0, 0}, 0, 1.0), local);
    }
};

QTEST_APPLESS_MAIN(TestViewportGizmo)
#include "test_viewport_gizmo.moc"
