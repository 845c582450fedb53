// Authoring from nothing in the real window (Xvfb): File > New's templates give a scene that is lit
// and framed (Empty says why it is black), a sphere added to the Studio template with its material
// turned red renders red in the path-traced view, and the gizmo's local-axes toggle moves a turned
// node along its own axis.
#include "test_viewport_scene.h"
#include "window_options.h"

#include "editor/document/edit_operations.h"
#include "editor/document/scene_templates.h"
#include "editor/history_view/command_labels.h"
#include "editor/main_window/main_window.h"
#include "editor/viewport/render_view.h"
#include "editor/viewport/viewport.h"
#include "scene/history/asset_commands.h"
#include "scene/history/set_node_field.h"

#include <QAction>
#include <QMouseEvent>
#include <QTemporaryDir>
#include <QtTest>

#include <filesystem>

using namespace glint;
using namespace glint::editor;

namespace {


void sendMouse(QWidget& w, QEvent::Type type, QPointF at, Qt::MouseButton button, Qt::MouseButtons buttons) {
    QMouseEvent event(type, at, w.mapToGlobal(at), button, buttons, Qt::NoModifier);
    QCoreApplication::sendEvent(&w, &event);
}


int nodesWith(const Scene& scene, auto predicate) {
    int n = 0;
    for (const auto& [id, node] : scene.nodes()) n += predicate(node) ? 1 : 0;
    return n;
}

} // namespace

class TestAuthoring : public QObject {
    Q_OBJECT
    QTemporaryDir temp_;

    // Triggers File > New from template > `kind` and waits until the path-traced view has `spp`
    // samples of the new scene.
    static void startFrom(MainWindow& window, SceneTemplate kind, int spp) {
        auto* action = window.findChild<QAction*>(templateActionId(kind));
        QVERIFY2(action, templateActionId(kind));
        RenderView& view = window.viewport()->view();
        const int uploads = view.stats().uploads;
        action->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(view.stats().uploads > uploads && view.stats().samples >= spp && !view.stats().preparing, 60000);
    }

private slots:
    void initTestCase() { QVERIFY(temp_.isValid()); }

    // Each template: its content, and the view it starts with. Lit templates are neither black nor
    // blown out (mean of the middle of the view between 0.05 and 0.85 of white) with no "nothing
    // emits light" hint; Empty shows the hint.
    void templatesStartLitAndFramed() {
        MainWindow window(glint::editor::test::windowOptions(temp_.filePath("autosave-templates")));
        window.resize(640, 480);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        RenderView& view = window.viewport()->view();
        for (const SceneTemplate kind : kSceneTemplates) {
            startFrom(window, kind, 4);
            const Scene& scene = window.document().scene();
            const QString name = templateTitle(kind);
            QVERIFY2(!window.document().isModified(), qPrintable(name));
            QVERIFY2(window.document().filePath().isEmpty(), qPrintable(name)); // untitled
            const QImage shot = view.grabFramebuffer();
            shot.save(QStringLiteral(GLINT_TEST_OUTPUT_DIR "/authoring_%1.png").arg(templateActionId(kind)));
            // The middle of the view: inside the camera's frame whatever bars its aspect leaves beside it.
            const QRect middle(shot.width() * 3 / 10, shot.height() * 3 / 10, shot.width() * 2 / 5, shot.height() * 2 / 5);
            const double mean = glint::test::imageStats(shot.copy(middle)).mean;
            qInfo("%s: %zu nodes, view mean %.1f, hint '%s'", qPrintable(name), scene.nodes().size(), mean,
                  qPrintable(view.stats().hint));
            if (kind == SceneTemplate::Empty) {
                QCOMPARE(scene.nodes().size(), std::size_t{0});
                QVERIFY(!view.stats().hint.isEmpty());
                continue;
            }
            QVERIFY2(view.stats().hint.isEmpty(), qPrintable(name + ": " + view.stats().hint));
            QVERIFY2(mean > 0.05 && mean < 0.85, qPrintable(name)); // neither black nor blown out
            QVERIFY2(nodesWith(scene, [](const Node& n) { return n.get<Camera>() != nullptr; }) == 1, qPrintable(name));
            if (kind == SceneTemplate::Studio) {
                QVERIFY(std::filesystem::exists(scene.settings.environment.file));
                QCOMPARE(nodesWith(scene, [](const Node& n) { return n.get<Shape>() && n.get<Shape>()->kind == ShapeKind::GroundPlane; }), 1);
            }
            if (kind == SceneTemplate::SunAndSky)
                QCOMPARE(nodesWith(scene, [](const Node& n) { return n.get<Light>() && n.get<Light>()->type == LightType::Sun; }), 1);
            if (kind == SceneTemplate::CornellBox || kind == SceneTemplate::CornellBoxInFog)
                QCOMPARE(scene.nodes().size(), std::size_t{9});
            QCOMPARE(scene.settings.fog.enabled(), kind == SceneTemplate::CornellBoxInFog);
        }
        // File > New is the Studio template.
        window.findChild<QAction*>("file.new")->trigger();
        QVERIFY(!window.document().scene().settings.environment.file.empty());
    }

    // A model with no light of its own (lit only by an emissive texture here): Add > Light > Studio
    // environment lights it as the Studio template is, in one undo step, and the viewport's note
    // goes; undo brings the dark scene and its note back.
    void studioEnvironmentLightsAnUnlitModel() {
        MainWindow window(glint::editor::test::windowOptions(temp_.filePath("autosave-studio-light")));
        window.resize(640, 480);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.openFile(QStringLiteral(GLINT_TEST_DATA_DIR "/gltf/EmissiveLabel/EmissiveLabel.gltf")));
        RenderView& view = window.viewport()->view();
        QTRY_VERIFY_WITH_TIMEOUT(view.stats().hint.startsWith("Only emissive textures give light"), 30000);
        const ProjectSettings before = window.document().scene().settings;
        auto* studio = window.findChild<QAction*>("add.light.studio_environment");
        QVERIFY(studio);
        studio->trigger();
        const ProjectSettings lit = window.document().scene().settings;
        QCOMPARE(lit, withStudioLighting(before));
        // The undo history names the action, not the generic settings edit it is made of.
        const Document& document = window.document();
        QCOMPARE(commandLabel(document.history().label(document.history().index() - 1)), QString("Add studio environment"));
        QCOMPARE(std::filesystem::path(lit.environment.file).filename().string(), std::string("studio_small_03_1k.hdr"));
        QVERIFY(std::filesystem::exists(lit.environment.file));
        QVERIFY2(view.stats().hint.isEmpty(), qPrintable(view.stats().hint));
        QTRY_VERIFY_WITH_TIMEOUT(view.stats().samples >= 2 && !view.stats().preparing, 60000);
        QVERIFY2(view.stats().error.isEmpty(), qPrintable(view.stats().error));
        window.document().undo();
        QCOMPARE(window.document().scene().settings, before);
        QVERIFY(view.stats().hint.startsWith("Only emissive textures give light"));
    }

    // Studio, Add > Sphere, its own material made red: the sphere's pixels in the path-traced view
    // turn from grey to red (red over twice green and blue), and undo brings the grey back.
    void aSphereWithANewRedMaterialRendersRed() {
        MainWindow window(glint::editor::test::windowOptions(temp_.filePath("autosave-red")));
        window.resize(640, 480);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        startFrom(window, SceneTemplate::Studio, 1);
        Document& document = window.document();
        QCOMPARE(addNode(document, "Sphere", defaultShape(ShapeKind::Sphere)), QString());
        const NodeId sphere = document.selection().front();
        // It rests on the ground plane under the view's focus.
        const float radius = document.scene().at(sphere).get<Shape>()->radius;
        QVERIFY(std::abs(document.scene().at(sphere).local.translation.y - radius) < 1e-4f);
        // A light added next hangs above the sphere, not inside it (the focus is inside the sphere).
        QCOMPARE(addNode(document, "Lamp", defaultLight(LightType::Point)), QString());
        const NodeId lamp = document.selection().front();
        QVERIFY(document.scene().at(lamp).local.translation.y > 2.0f * radius);
        document.undo();
        const MaterialId materialId = document.scene().at(sphere).get<Shape>()->material;
        QVERIFY(document.scene().materials.contains(materialId));
        RenderView& view = window.viewport()->view();
        document.setSelection({}); // no gizmo over the sphere
        const auto centre = view.project(glm::dvec3(document.scene().worldFromNode(sphere)[3]));
        QVERIFY(centre);
        const qreal ratio = view.devicePixelRatioF();
        const QPoint at((centre->toPoint().x()) * ratio, (centre->toPoint().y()) * ratio);
        QTRY_VERIFY_WITH_TIMEOUT(view.stats().samples >= 8 && !view.stats().preparing, 60000);
        const glm::dvec3 before = glint::test::meanRgbAround(view.grabFramebuffer(), at, 2);

        Material red = document.scene().materials.at(materialId);
        red.baseColorFactor = glm::vec4(0.8f, 0.02f, 0.02f, 1.0f);
        long long paints = view.stats().paints;
        document.push(std::make_unique<SetAsset<Material>>(materialId, red));
        QTRY_VERIFY_WITH_TIMEOUT(view.stats().paints > paints + 1, 60000); // the edit's first frame is on screen
        QTRY_VERIFY_WITH_TIMEOUT(view.stats().samples >= 8, 60000);
        const glm::dvec3 after = glint::test::meanRgbAround(view.grabFramebuffer(), at, 2);
        qInfo("sphere centre before (%.0f %.0f %.0f), after (%.0f %.0f %.0f)", before.x, before.y, before.z, after.x, after.y, after.z);
        QVERIFY(std::abs(before.x - before.y) < 0.2 * before.x + 4.0); // grey first
        QVERIFY(after.x > 2.0 * after.y && after.x > 2.0 * after.z && after.x > 40.0);
        paints = view.stats().paints;
        document.undo();
        QTRY_VERIFY_WITH_TIMEOUT(view.stats().paints > paints + 1, 60000);
        QTRY_VERIFY_WITH_TIMEOUT(view.stats().samples >= 8, 60000);
        const glm::dvec3 undone = glint::test::meanRgbAround(view.grabFramebuffer(), at, 2);
        QVERIFY(undone.x < 2.0 * undone.y);
    }

    // A box turned 90 degrees about Y. World axes: the X handle is the world's X. Local axes (the
    // action, key L): the X handle is the box's own X (the world's -Z), and dragging it moves the
    // box along that axis only.
    void localAxesMoveAlongTheNodesOwnAxis() {
        MainWindow window(glint::editor::test::windowOptions(temp_.filePath("autosave-axes")));
        window.resize(640, 480);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        startFrom(window, SceneTemplate::Studio, 1);
        Document& document = window.document();
        QCOMPARE(addNode(document, "Box", defaultShape(ShapeKind::Box)), QString());
        const NodeId box = document.selection().front();
        Transform turned = document.scene().at(box).local;
        turned.rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(0.0f, 1.0f, 0.0f));
        document.push(std::make_unique<SetTransform>(box, turned));
        RenderView& view = window.viewport()->view();
        QCOMPARE(view.gizmoFrame(box).axes[0].x, 1.0);

        QAction* local = window.viewport()->localAxesAction();
        QCOMPARE(local->shortcut(), QKeySequence(Qt::Key_L));
        local->trigger();
        QCOMPARE(view.gizmoSpace(), GizmoSpace::Local);
        const GizmoFrame frame = view.gizmoFrame(box);
        QVERIFY(std::abs(frame.axes[0].z + 1.0) < 1e-6); // the box's X is the world's -Z
        const auto handle = view.project(frame.origin + 0.8 * frame.size * frame.axes[0]);
        const auto origin = view.project(frame.origin);
        QVERIFY(handle && origin);
        const QPointF along = (*handle - *origin) / std::hypot((*handle - *origin).x(), (*handle - *origin).y());
        sendMouse(view, QEvent::MouseButtonPress, *handle, Qt::LeftButton, Qt::LeftButton);
        for (int i = 1; i <= 4; ++i) sendMouse(view, QEvent::MouseMove, *handle + along * (8.0 * i), Qt::NoButton, Qt::LeftButton);
        sendMouse(view, QEvent::MouseButtonRelease, *handle + along * 32.0, Qt::LeftButton, Qt::NoButton);
        const glm::vec3 moved = document.scene().at(box).local.translation - turned.translation;
        qInfo("moved by (%.3f %.3f %.3f)", moved.x, moved.y, moved.z);
        QVERIFY(moved.z < -1e-3);                                              // along the box's +X
        QVERIFY(std::abs(moved.x) < 1e-4 && std::abs(moved.y) < 1e-4);        // and nothing else
        local->trigger();
        QCOMPARE(view.gizmoSpace(), GizmoSpace::World);
    }
};

QTEST_MAIN(TestAuthoring)
#include "test_authoring.moc"
