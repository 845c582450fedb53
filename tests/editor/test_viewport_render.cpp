// The viewport in a real window under Xvfb: it shows a non-black path-traced image within a few
// frames, a click selects the node under the cursor, a gizmo drag is one undo step whose undo
// restores the exact transform, navigation never dirties the file. 128x96 px, llvmpipe.
#include "test_viewport_scene.h"

#include "editor/document/edit_operations.h"
#include "editor/viewport/render_view.h"
#include "editor/viewport/viewport.h"
#include "scene/history/settings_commands.h"

#include <QAction>
#include <QElapsedTimer>
#include <QMainWindow>
#include <QMouseEvent>
#include <QSignalSpy>
#include <QtTest>

using namespace glint;
using namespace glint::editor;

namespace {

constexpr int kMaxWaitMs = 20000;

// Processes events until `done` or the time runs out; returns done().
template <class F> bool waitFor(F done, int ms = kMaxWaitMs) {
    QElapsedTimer t;
    t.start();
    while (!done() && t.elapsed() < ms) QTest::qWait(5);
    return done();
}

void sendMouse(QWidget& w, QEvent::Type type, QPointF at, Qt::MouseButton button, Qt::MouseButtons buttons) {
    QMouseEvent event(type, at, w.mapToGlobal(at), button, buttons, Qt::NoModifier);
    QCoreApplication::sendEvent(&w, &event);
}

} // namespace

class TestViewportRender : public QObject {
    Q_OBJECT
private slots:
    void init() {
        document_ = std::make_unique<Document>();
        scene_ = test::buildShapesScene(*document_);
        window_ = std::make_unique<QMainWindow>();
        viewport_ = new Viewport(*document_, window_.get());
        window_->setCentralWidget(viewport_);
        window_->resize(128, 96);
        window_->show();
        QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
    }
    void cleanup() {
        window_.reset();
        document_.reset();
    }

    void rendersANonBlackImageWithinFrames() {
        RenderView& view = viewport_->view();
        // N = 30 paints: the first frame of the still configuration already shows the scene.
        QVERIFY2(waitFor([&] { return view.stats().samples >= 4 || view.stats().paints >= 30; }), "no frames");
        QVERIFY2(view.stats().error.isEmpty(), qPrintable(view.stats().error));
        QVERIFY(view.stats().paints <= 30);
        const test::ImageStats s = test::imageStats(view.grabFramebuffer());
        qInfo("paints %lld, samples %d, last frame %.1f ms, paint %.1f ms, non-black %.3f, mean %.3f", view.stats().paints,
              view.stats().samples, view.stats().frameMs, view.stats().paintMs, s.nonBlack, s.mean);
        QVERIFY(s.nonBlack > 0.95); // grey sky and lit shapes everywhere
        QVERIFY(s.mean > 0.15);
    }

    // Structural edits (hide, delete) need a new GPU scene: the path-traced image must come back
    // each time, never the preview's bare clear colour.
    void structuralEditsBringThePathTracedImageBack() {
        RenderView& view = viewport_->view();
        QVERIFY2(waitFor([&] { return view.stats().samples >= 4; }), "no first image");
        const auto sphere = view.project({-1.2, 0.0, 0.0});
        QVERIFY(sphere);
        const auto expectImage = [&](const char* after) {
            const int uploads = view.stats().uploads;
            QVERIFY2(waitFor([&] { return view.stats().uploads > uploads && view.stats().samples >= 4; }), after);
            QVERIFY2(view.stats().error.isEmpty(), qPrintable(view.stats().error));
            const QImage image = view.grabFramebuffer().convertToFormat(QImage::Format_RGB32);
            QVERIFY2(test::clearColourShare(image) < 0.1, after);
            const QRgb onSphere = image.pixel(sphere->toPoint() * image.width() / view.width());
            QVERIFY2(qRed(onSphere) > 60, after); // the sphere, lit by the grey sky
        };
        QCOMPARE(setVisible(*document_, scene_.ground, false), QString());
        expectImage("after hiding the ground");
        document_->push(std::make_unique<RemoveNode>(scene_.box));
        expectImage("after deleting the box");
        document_->undo();
        expectImage("after undoing the delete");
    }

    // A scene with nothing that emits light renders black: the viewport says why over the image,
    // and the note goes as soon as the environment has a colour again (one undo).
    void blackSceneSaysNothingEmitsLight() {
        RenderView& view = viewport_->view();
        QVERIFY(view.stats().hint.isEmpty()); // the grey sky lights the shapes
        ProjectSettings dark = document_->scene().settings;
        dark.environment.color = glm::vec3(0.0f);
        document_->push(std::make_unique<SetProjectSettings>(dark));
        QVERIFY(view.stats().hint.contains("emits light"));
        QVERIFY(waitFor([&] { return view.stats().samples >= 2; }));
        const test::ImageStats black = test::imageStats(view.grabFramebuffer());
        qInfo("black scene with the note: non-black %.3f, mean %.4f", black.nonBlack, black.mean);
        QVERIFY(black.mean > 0.0 && black.mean < 0.3); // light text over black (the lit view: 0.75)
        document_->undo();
        QVERIFY(view.stats().hint.isEmpty());
    }

    // A file lit only by an emissive texture (a label, a helmet's lamps) renders mostly dark: the
    // viewport says that, not that nothing emits light; an environment colour lights it and the note
    // goes (one undo brings it back).
    void emissiveTexturesAloneAreNamed() {
        RenderView& view = viewport_->view();
        QCOMPARE(document_->open(QStringLiteral(GLINT_TEST_DATA_DIR "/gltf/EmissiveLabel/EmissiveLabel.gltf")), QString());
        QVERIFY2(waitFor([&] { return view.stats().samples >= 1; }), "no first image");
        QVERIFY2(view.stats().error.isEmpty(), qPrintable(view.stats().error));
        QVERIFY2(view.stats().hint.startsWith("Only emissive textures give light"), qPrintable(view.stats().hint));
        ProjectSettings sky = document_->scene().settings;
        sky.environment.color = glm::vec3(0.5f);
        document_->push(std::make_unique<SetProjectSettings>(sky));
        QVERIFY2(view.stats().hint.isEmpty(), qPrintable(view.stats().hint));
        document_->undo();
        QVERIFY(view.stats().hint.startsWith("Only emissive textures give light"));
    }

    void rasterPreviewDrawsTheShapes() {
        RenderView& view = viewport_->view();
        for (QAction* action : viewport_->viewModeActions())
            if (action->data().toInt() == int(ViewMode::Solid)) action->trigger();
        QCOMPARE(view.mode(), ViewMode::Solid);
        const long long before = view.stats().paints;
        view.update();
        QVERIFY(waitFor([&] { return view.stats().paints > before; }));
        QVERIFY2(view.stats().error.isEmpty(), qPrintable(view.stats().error));
        const QImage image = view.grabFramebuffer().convertToFormat(QImage::Format_RGB32);
        const auto sphere = view.project({-1.2, 0.0, 0.0});
        const QRgb background = image.pixel(image.width() / 2, 1); // the sky: the clear colour
        const QRgb onSphere = image.pixel(sphere->toPoint() * image.width() / view.width());
        QCOMPARE(qRed(background), 56); // 0.22 * 255
        QVERIFY(qRed(onSphere) > 120);   // lit grey surface facing the headlight
        view.setMode(ViewMode::Wireframe);
        QVERIFY(waitFor([&] { return view.stats().paints > before + 1; }));
        const test::ImageStats wire = test::imageStats(view.grabFramebuffer());
        QVERIFY(wire.mean > 0.2 && wire.mean < 0.8); // lines over the clear colour
    }

    void bvhBoxesAreDrawnOverThePreview() {
        RenderView& view = viewport_->view();
        view.setMode(ViewMode::BvhBoxes);
        const long long before = view.stats().paints;
        QVERIFY(waitFor([&] { return view.stats().paints > before; }));
        const QImage image = view.grabFramebuffer().convertToFormat(QImage::Format_RGB32);
        int boxPixels = 0; // the box colour (80, 220, 255) appears nowhere else
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const QRgb c = image.pixel(x, y);
                boxPixels += qBlue(c) > 200 && qGreen(c) > 150 && qRed(c) < 140;
            }
        QVERIFY(boxPixels > 40);
    }

    void pixelInspectorReportsLinearValues() {
        RenderView& view = viewport_->view();
        QVERIFY(waitFor([&] { return view.stats().samples >= 4; }));
        viewport_->inspectAction()->setChecked(true);
        QSignalSpy inspected(&view, &RenderView::pixelInspected);
        QTest::mouseClick(&view, Qt::LeftButton, {}, QPoint(64, 4)); // the grey sky: radiance 0.8
        QCOMPARE(inspected.size(), 1);
        for (int c = 1; c <= 3; ++c) QVERIFY(std::abs(inspected.first().at(c).toFloat() - 0.8f) < 1e-3f);
        QVERIFY(document_->selection().empty()); // inspecting does not select
    }

    void abSnapshotComparesTwoSettings() {
        RenderView& view = viewport_->view();
        QVERIFY(waitFor([&] { return view.stats().samples >= 2; }));
        viewport_->snapshotAction()->trigger();
        QVERIFY(view.hasSnapshot());
        QVERIFY(viewport_->compareAction()->isEnabled());
        ProjectSettings settings = document_->scene().settings;
        settings.environment.color = glm::vec3(0.0f); // B: a black sky
        document_->push(std::make_unique<SetProjectSettings>(settings));
        viewport_->compareAction()->setChecked(true);
        QVERIFY(waitFor([&] { return view.stats().samples >= 4; }));
        const QImage image = view.grabFramebuffer().convertToFormat(QImage::Format_RGB32);
        QVERIFY(qGreen(image.pixel(10, 2)) > 100); // left: A, the grey sky
        QVERIFY(qGreen(image.pixel(image.width() - 10, 2)) < 20); // right: B, the live black sky
    }

    void clickSelectsTheNodeUnderTheCursor() {
        RenderView& view = viewport_->view();
        const auto sphere = view.project({-1.2, 0.0, 0.0});
        const auto box = view.project({1.2, 0.0, 0.0});
        QVERIFY(sphere && box);
        QTest::mouseClick(&view, Qt::LeftButton, {}, sphere->toPoint());
        QCOMPARE(document_->selection(), std::vector<NodeId>{scene_.sphere});
        QTest::mouseClick(&view, Qt::LeftButton, Qt::ShiftModifier, box->toPoint());
        QCOMPARE(document_->selection(), (std::vector<NodeId>{scene_.sphere, scene_.box}));
        QTest::mouseClick(&view, Qt::LeftButton, {}, QPoint(64, 2)); // the sky
        QVERIFY(document_->selection().empty());
        QVERIFY(!document_->isModified()); // selecting never dirties the file
    }

    void gizmoDragIsOneUndoStepWithExactUndo() {
        RenderView& view = viewport_->view();
        document_->setSelection({scene_.box});
        const Transform before = document_->scene().at(scene_.box).local;
        const std::size_t steps = document_->history().count();
        const GizmoFrame frame = view.gizmoFrame(scene_.box);
        const auto grab = view.project(frame.origin + 0.7 * frame.size * frame.axes[0]);
        QVERIFY(grab);
        sendMouse(view, QEvent::MouseButtonPress, *grab, Qt::LeftButton, Qt::LeftButton);
        for (int i = 1; i <= 6; ++i)
            sendMouse(view, QEvent::MouseMove, *grab + QPointF(3.0 * i, 1.0 * i), Qt::NoButton, Qt::LeftButton);
        sendMouse(view, QEvent::MouseButtonRelease, *grab + QPointF(18, 6), Qt::LeftButton, Qt::NoButton);
        const Transform after = document_->scene().at(scene_.box).local;
        QCOMPARE(document_->history().count(), steps + 1);
        QVERIFY(after.translation.x > before.translation.x + 0.05f); // moved right along X only
        QCOMPARE(after.translation.y, before.translation.y);
        QCOMPARE(after.translation.z, before.translation.z);
        document_->undo();
        QCOMPARE(document_->scene().at(scene_.box).local, before);
        document_->redo();
        QCOMPARE(document_->scene().at(scene_.box).local, after);
    }

    void navigationDoesNotDirtyTheDocument() {
        RenderView& view = viewport_->view();
        const ViewCamera start = view.camera();
        sendMouse(view, QEvent::MouseButtonPress, {64, 48}, Qt::MiddleButton, Qt::MiddleButton);
        sendMouse(view, QEvent::MouseMove, {90, 40}, Qt::NoButton, Qt::MiddleButton);
        sendMouse(view, QEvent::MouseButtonRelease, {90, 40}, Qt::MiddleButton, Qt::NoButton);
        QVERIFY(!(view.camera() == start));
        QVERIFY(!document_->isModified());
        QCOMPARE(document_->history().count(), std::size_t(3));
    }

    void makeSceneCameraIsUndoable() {
        const std::size_t nodes = document_->scene().nodeCount();
        const NodeId camera = viewport_->makeSceneCamera();
        QCOMPARE(document_->scene().nodeCount(), nodes + 1);
        const glm::vec3 position = glm::vec3(document_->scene().worldFromNode(camera)[3]);
        QVERIFY(glm::length(position - glm::vec3(viewport_->view().camera().position())) < 1e-5f);
        document_->undo();
        QCOMPARE(document_->scene().nodeCount(), nodes);
    }

private:
    std::unique_ptr<Document> document_;
    test::ShapesScene scene_;
    std::unique_ptr<QMainWindow> window_;
    Viewport* viewport_ = nullptr;
};

int main(int argc, char** argv) {
    glint::test::prepareGlApplication();
    QApplication app(argc, argv);
    TestViewportRender test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_viewport_render.moc"
