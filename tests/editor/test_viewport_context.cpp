// Floating or re-docking the viewport can destroy its GL context (always so without
// Qt::AA_ShareOpenGLContexts, as here): the viewport then rebuilds the GPU scene from the
// document in the new context and keeps showing the same picture. 128x96 px, llvmpipe.
#include "test_viewport_scene.h"

#include "editor/viewport/render_view.h"
#include "editor/viewport/viewport.h"
#include "scene/history/settings_commands.h"

#include <QMainWindow>
#include <QtTest>

using namespace glint;
using namespace glint::editor;

class TestViewportContext : public QObject {
    Q_OBJECT
private slots:
    void redockingRebuildsTheGpuScene() {
        Document document;
        test::buildShapesScene(document);
        QMainWindow window;
        auto* viewport = new Viewport(document, &window);
        window.setCentralWidget(viewport);
        window.resize(128, 96);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        RenderView& view = viewport->view();
        QTRY_VERIFY_WITH_TIMEOUT(view.stats().samples >= 2, 20000);
        QCOMPARE(view.stats().contexts, 1);
        const double before = test::imageStats(view.grabFramebuffer()).mean;

        // Float the viewport into a window of its own, as a dock widget does.
        QWidget floating;
        floating.resize(128, 96);
        viewport->setParent(&floating);
        viewport->resize(128, 96);
        viewport->show();
        floating.show();
        QVERIFY(QTest::qWaitForWindowExposed(&floating));
        QTRY_VERIFY_WITH_TIMEOUT(view.stats().contexts >= 2 && view.stats().samples >= 2, 20000);
        QVERIFY2(view.stats().error.isEmpty(), qPrintable(view.stats().error));
        const double after = test::imageStats(view.grabFramebuffer()).mean;
        qInfo("mean before %.4f, after %.4f, contexts %d", before, after, view.stats().contexts);
        QVERIFY(after > 0.15);
        QVERIFY(std::abs(after - before) < 0.05); // the same scene, a few samples apart
        // An edit after the move reaches the new context's GPU scene.
        ProjectSettings settings = document.scene().settings;
        settings.environment.color = glm::vec3(0.0f); // the sky goes black: most of the picture
        document.push(std::make_unique<SetProjectSettings>(settings));
        const bool changed = QTest::qWaitFor([&] { return test::imageStats(view.grabFramebuffer()).mean < 0.2; }, 20000);
        qInfo("after the edit: samples %d, paints %lld, error '%s', mean %.4f", view.stats().samples, view.stats().paints,
              qPrintable(view.stats().error), test::imageStats(view.grabFramebuffer()).mean);
        QVERIFY(changed);
        delete viewport;
    }
};

int main(int argc, char** argv) {
    glint::test::prepareGlApplication(false);
    QApplication app(argc, argv);
    TestViewportContext test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_viewport_context.moc"
