// Click picking without building on the GUI thread, and clicks on lights and cameras.
// - The picker built on the preparation's worker (over the GPU scene's mesh BVHs) picks the same node
//   at the same distance as one built on its own, for a 48x32 grid of rays over 12 meshes, shapes, a
//   sphere lamp, a mesh instanced twice and a hidden node (tolerance 1e-4 relative in t).
// - In the viewport (160x120 px, Xvfb, llvmpipe): a click on a sphere lamp (away from its icon), on a
//   point light's icon and on a camera's icon (5 px off their centres, within the 8 px pick radius)
//   selects that node, 12 px off picks what lies behind; a
//   transform edit picks at the new place at once; after a structural edit picking reports nothing
//   (never a wrong node) until the new picker arrives with the preparation.
// Prints the GUI-thread cost the first click after an edit had before (a synchronous picker build
// of 209,088 triangles) and has now (a retarget), for docs/PERFORMANCE.md.
#include "shown_viewport.h"
#include "test_viewport_scene.h"

#include "editor/viewport/node_icons.h"
#include "editor/viewport/render_view.h"
#include "editor/viewport/scene_preparer.h"
#include "editor/viewport/view_picking.h"
#include "editor/viewport/viewport.h"
#include "scene/history/set_node_field.h"
#include "tests/cli/generated_scenes.h"

#include <QElapsedTimer>
#include <QMainWindow>
#include <QtTest>

#include <thread>

using namespace glint;
using namespace glint::editor;

namespace {

NodeId addNode(Scene& scene, const char* name, Component component, glm::vec3 at) {
    Node node;
    node.name = name;
    node.local.translation = at;
    node.component = std::move(component);
    return scene.addNode(std::move(node));
}

Light lamp(float radius) {
    Light light;
    light.radius = radius;
    return light;
}

// 12 grids (manyGridsScene), a second instance of the first grid's mesh, shapes, a sphere lamp and
// a hidden sphere.
Scene mixedScene() {
    Scene scene = test::manyGridsScene(12, 12);
    const NodeId first = scene.roots().front();
    Node copy = scene.at(first);
    copy.id = {};
    copy.local.translation.y = 0.3f;
    copy.local.rotation = glm::angleAxis(0.5f, glm::vec3(0, 1, 0));
    scene.addNode(std::move(copy));
    Shape box;
    box.kind = ShapeKind::Box;
    addNode(scene, "box", box, {2.0f, 0.0f, -1.0f});
    addNode(scene, "sphere", Shape{}, {-3.0f, 0.2f, 0.5f});
    addNode(scene, "lamp", lamp(0.4f), {0.5f, 0.4f, -2.0f});
    const NodeId hidden = addNode(scene, "hidden", Shape{}, {1.0f, 0.5f, -0.5f});
    scene.setVisible(hidden, false);
    return scene;
}

QPoint pixelOf(RenderView& view, glm::dvec3 world) {
    const auto p = view.project(world);
    return p ? p->toPoint() : QPoint(-1, -1);
}

void click(RenderView& view, Document& document, QPoint at) {
    document.setSelection({});
    QTest::mouseClick(&view, Qt::LeftButton, Qt::NoModifier, at);
}

} // namespace

class TestViewportClickPick : public QObject {
    Q_OBJECT
private slots:
    void workerPickerPicksAsASynchronousOne() {
        const Scene scene = mixedScene();
        std::shared_ptr<ScenePicker> fromWorker;
        std::thread worker([&] {
            renderer::MeshBvhCache cache;
            const renderer::PreparedScene prepared = renderer::prepareScene(scene, {}, renderer::TextureLimits{}, cache);
            fromWorker = pickerFromPreparation(scene, prepared.meshes);
        });
        worker.join();
        const ScenePicker here(scene);
        int hits = 0, lamps = 0;
        for (int j = 0; j < 32; ++j)
            for (int i = 0; i < 48; ++i) {
                // Slanted rays from above, so the instanced copy, shapes and lamp shadow the grids.
                const bvh::Ray ray{{-5.0f + 10.0f * float(i) / 47.0f, 4.0f, -4.0f + 5.0f * float(j) / 31.0f}, {0.1f, -1.0f, 0.05f}};
                const PickResult a = fromWorker->pick(ray), b = here.pick(ray);
                QCOMPARE(a.node, b.node);
                QVERIFY(std::abs(a.t - b.t) <= 1e-4f * std::max(1.0f, b.t));
                hits += b.node.valid();
                lamps += b.node.valid() && scene.at(b.node).get<Light>() != nullptr;
            }
        QVERIFY2(hits > 300 && lamps > 0, qPrintable(QString("hits %1, lamp hits %2").arg(hits).arg(lamps)));
    }

    // What the first click after an edit cost on the GUI thread before (the whole picker) and now
    // (a transform edit: the top level over the same mesh BVHs).
    void pickerCosts() {
        const Scene scene = test::manyGridsScene(24, 66);
        QElapsedTimer clock;
        clock.start();
        ScenePicker picker(scene);
        const double build = double(clock.nsecsElapsed()) / 1e6;
        clock.restart();
        picker.retarget(scene);
        const double retarget = double(clock.nsecsElapsed()) / 1e6;
        qInfo("209,088 triangles in 24 meshes: a picker built from scratch %.0f ms, retargeted %.2f ms", build, retarget);
        QVERIFY(picker.pick({{0.5f, 3.0f, -1.5f}, {0.0f, -1.0f, 0.0f}}).node.valid());
    }

    void clicksSelectLampsAndCameras() {
        Document document;
        const test::ShapesScene shapes = test::buildShapesScene(document);
        Scene& scene = document.scene();
        const NodeId sphereLamp = addNode(scene, "sphere lamp", lamp(0.5f), {0.0f, 1.2f, 0.0f});
        const NodeId pointLight = addNode(scene, "point light", lamp(0.0f), {-1.6f, 1.3f, 0.0f});
        const NodeId camera = addNode(scene, "camera", Camera{}, {1.9f, 1.3f, 0.0f});
        test::ShownViewport shown(document);
        QVERIFY(QTest::qWaitForWindowExposed(&shown.window));
        RenderView& view = shown.view();
        QTRY_VERIFY_WITH_TIMEOUT(view.picking().current(), 60000);
        QCOMPARE(view.picking().builtHere(), 0); // it came with the preparation

        QTRY_VERIFY_WITH_TIMEOUT(view.stats().samples >= 4, 60000);
        view.grabFramebuffer().save(QStringLiteral(GLINT_TEST_OUTPUT_DIR "/viewport_icons.png")); // to look at

        // The lamp's sphere away from its icon: a ray pick.
        const QPoint lampSurface = pixelOf(view, {0.0, 0.85, 0.0});
        QVERIFY(QLineF(lampSurface, pixelOf(view, {0.0, 1.2, 0.0})).length() > kIconPickRadius + 1.0);
        click(view, document, lampSurface);
        QCOMPARE(document.selection(), std::vector<NodeId>{sphereLamp});
        click(view, document, pixelOf(view, {-1.6, 1.3, 0.0}) + QPoint(3, -4));
        QCOMPARE(document.selection(), std::vector<NodeId>{pointLight});
        click(view, document, pixelOf(view, {1.9, 1.3, 0.0}) + QPoint(-4, 3));
        QCOMPARE(document.selection(), std::vector<NodeId>{camera});
        const QPoint besideCamera = pixelOf(view, {1.9, 1.3, 0.0}) + QPoint(0, 12); // outside the icon: what the ray hits
        const NodeId behind = view.picker().pick(view.rayAt(besideCamera)).node;
        QVERIFY(behind != camera);
        click(view, document, besideCamera);
        QCOMPARE(document.selection(), behind.valid() ? std::vector<NodeId>{behind} : std::vector<NodeId>{});
        click(view, document, pixelOf(view, {-1.2, 0.0, 0.0}));
        QCOMPARE(document.selection(), std::vector<NodeId>{shapes.sphere});

        // A transform edit picks at the new place at once, on the retargeted picker.
        Transform moved = scene.at(shapes.box).local;
        moved.translation.y += 0.8f;
        document.push(std::make_unique<SetTransform>(shapes.box, moved));
        QCOMPARE(view.pickAt(QPointF(pixelOf(view, {1.2, 0.8, 0.4}))), shapes.box);
        QCOMPARE(view.pickAt(QPointF(pixelOf(view, {1.2, -0.3, 0.45}))), shapes.ground);

        // A structural edit: nothing (never a wrong node) until the new picker comes, then the new node.
        const NodeId added = test::addShape(document, "added", ShapeKind::Sphere, {0.0f, 0.0f, 1.0f});
        const QPointF at(pixelOf(view, {0.0, 0.0, 1.5}));
        QVERIFY(!view.picking().current());
        QCOMPARE(view.pickAt(at), NodeId{});
        QTRY_VERIFY_WITH_TIMEOUT(view.picking().current(), 60000);
        QCOMPARE(view.pickAt(at), added);
        QCOMPARE(view.picking().builtHere(), 0);
    }

    // The raster views prepare no GPU scene: a picker-only job on a worker brings the picker.
    void rasterViewsGetAPickerToo() {
        Document document;
        const test::ShapesScene shapes = test::buildShapesScene(document);
        test::ShownViewport shown(document);
        QVERIFY(QTest::qWaitForWindowExposed(&shown.window));
        RenderView& view = shown.view();
        view.setMode(ViewMode::Solid);
        QTRY_VERIFY_WITH_TIMEOUT(view.picking().current(), 60000);
        const NodeId added = test::addShape(document, "added", ShapeKind::Box, {0.0f, 0.0f, 1.0f}, glm::vec3(0.5f));
        QTRY_VERIFY_WITH_TIMEOUT(view.picking().current(), 60000);
        QVERIFY(view.picking().builtHere() >= 1);
        QCOMPARE(view.pickAt(QPointF(pixelOf(view, {0.0, 0.0, 1.25}))), added);
        QCOMPARE(view.pickAt(QPointF(pixelOf(view, {-1.2, 0.0, 0.0}))), shapes.sphere);
    }
};

int main(int argc, char** argv) {
    glint::test::prepareGlApplication();
    QApplication app(argc, argv);
    TestViewportClickPick test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_viewport_click_pick.moc"
