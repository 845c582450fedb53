// Where the viewport looks when a scene is opened: through the camera a render uses (active, else
// first), orbiting at the depth of the scene's centre; without a camera, the whole scene framed from
// the CLI default view's direction; an empty scene from 5 m. No window, no GL.
#include "editor/viewport/initial_view.h"
#include "scene/core/default_view.h"

#include <QtTest>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

using namespace glint;
using namespace glint::editor;

namespace {

bool near(const glm::dvec3& a, const glm::dvec3& b, double tol) { return glm::length(a - b) <= tol; }

NodeId addBox(Scene& scene, glm::vec3 at, glm::vec3 size) {
    Node node;
    node.name = "box";
    node.local.translation = at;
    Shape shape;
    shape.kind = ShapeKind::Box;
    shape.size = size;
    node.component = shape;
    return scene.addNode(std::move(node));
}

NodeId addCamera(Scene& scene, const char* name, glm::vec3 at, glm::vec3 lookAt, float yfov, float focus = 1.0f) {
    Node node;
    node.name = name;
    node.local.translation = at;
    node.local.rotation = glm::quatLookAt(glm::normalize(lookAt - at), glm::vec3(0, 1, 0));
    Camera camera;
    camera.yfov = yfov;
    camera.focusDistance = focus;
    node.component = camera;
    return scene.addNode(std::move(node));
}

} // namespace

class TestViewportInitialView : public QObject {
    Q_OBJECT
private slots:
    void emptySceneIsSeenFromFiveMetresAboveTheFront() {
        const ViewCamera view = initialView(Scene{}, 1.5);
        QVERIFY(near(view.target, {0, 0, 0}, 1e-12));
        QCOMPARE(view.distance, 5.0);
        QVERIFY(near(-view.forward(), glm::dvec3(defaultViewFromCentre()), 1e-6));
    }

    void cameraLessSceneIsFramedWhole() {
        Scene scene;
        addBox(scene, {10, 2, -4}, {2, 2, 2});
        const ViewCamera view = initialView(scene, 1.0);
        QVERIFY(near(view.target, {10, 2, -4}, 1e-6));
        QVERIFY(near(-view.forward(), glm::dvec3(defaultViewFromCentre()), 1e-6));
        // The sphere around the box (radius sqrt 3) fits the 39.6-degree field with 10 % to spare.
        const double expected = 1.1 * std::sqrt(3.0) / std::sin(0.5 * double(view.yfov));
        QVERIFY(std::abs(view.distance - expected) < 1e-4);
        // Every corner of the box is inside the view.
        for (int i = 0; i < 8; ++i) {
            const glm::dvec3 corner(i & 1 ? 11 : 9, i & 2 ? 3 : 1, i & 4 ? -3 : -5);
            const glm::dvec3 p = projectToPixels(view, corner, 200, 200);
            QVERIFY(p.z > 0 && p.x > 0 && p.x < 200 && p.y > 0 && p.y < 200);
        }
    }

    void looksThroughTheActiveCameraElseTheFirst() {
        Scene scene;
        addBox(scene, {0, 0, 0}, {1, 1, 1});
        addCamera(scene, "first", {0, 0, 4}, {0, 0, 0}, 0.5f);
        const NodeId active = addCamera(scene, "active", {3, 3, 3}, {0, 0, 0}, 0.8f);
        ViewCamera view = initialView(scene, 1.0);
        QVERIFY(near(view.position(), {0, 0, 4}, 1e-5)); // no active camera: the first one
        QCOMPARE(view.yfov, 0.5f);
        QVERIFY(std::abs(view.distance - 4.0) < 1e-5); // orbits about the scene's centre
        scene.settings.activeCamera = active;
        view = initialView(scene, 1.0);
        QVERIFY(near(view.position(), {3, 3, 3}, 1e-5));
        QVERIFY(near(view.forward(), glm::normalize(glm::dvec3(-1, -1, -1)), 1e-5));
        QVERIFY(near(view.target, {0, 0, 0}, 1e-5));
        QCOMPARE(view.yfov, 0.8f);
    }

    void cameraFacingAwayOrbitsAboutItsFocus() {
        Scene scene;
        addBox(scene, {0, 0, 0}, {1, 1, 1});
        addCamera(scene, "away", {0, 0, 4}, {0, 0, 8}, 0.7f, 2.5f);
        const ViewCamera view = initialView(scene, 1.0);
        QVERIFY(near(view.position(), {0, 0, 4}, 1e-5));
        QVERIFY(std::abs(view.distance - 2.5) < 1e-6);
    }
};

QTEST_APPLESS_MAIN(TestViewportInitialView)
#include "test_viewport_initial_view.moc"
