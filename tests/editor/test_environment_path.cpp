// The environment image chosen in the Scene tab, as a new user does it (issue 17, item 3), in the
// real window under Xvfb: in an untitled scene Browse keeps the absolute path and the viewport shows
// the sky at once; Save As copies the image beside the scene and the document names the copy;
// reopening finds it; a missing image is said in the Scene tab.
#include "editor_fixtures.h"
#include "test_viewport_scene.h"

#include "editor/log/log_panel.h"
#include "editor/main_window/main_window.h"
#include "editor/properties/properties_panel.h"
#include "editor/viewport/render_view.h"
#include "editor/viewport/viewport.h"

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QLabel>
#include <QLineEdit>
#include <QSettings>
#include <QTemporaryDir>
#include <QTimer>
#include <QToolButton>

using namespace glint;
using namespace glint::editor;
using namespace glint::editor::test;

namespace {

// Clicks the Scene tab's Browse and answers the file dialog with `file`.
bool browseEnvironment(MainWindow& window, const QString& file) {
    auto* browse = fieldNamed<QToolButton>(window.sceneSettings(), "Choose an HDR environment file");
    if (!browse) return false;
    bool answered = false;
    QTimer::singleShot(0, [&] {
        auto* dialog = qobject_cast<QFileDialog*>(QApplication::activeModalWidget());
        if (!dialog) return;
        dialog->selectFile(file);
        QMetaObject::invokeMethod(dialog, "accept"); // a slot, protected in QFileDialog
        answered = true;
    });
    browse->click();
    return answered;
}

// The viewport's picture once it has samples of the current scene: its mean brightness.
double viewportBrightness(RenderView& view) {
    const int uploads = view.stats().uploads;
    if (!QTest::qWaitFor([&] { return view.stats().uploads > uploads && view.stats().samples >= 2; }, 30000)) return -1.0;
    return glint::test::imageStats(view.grabFramebuffer()).mean;
}

QLabel* environmentStatus(MainWindow& window) { return fieldNamed<QLabel>(window.sceneSettings(), "Environment image status"); }

} // namespace

class TestEnvironmentPath : public QObject {
    Q_OBJECT
private slots:
    void chosenInANewSceneSavedAndReopened() {
        QTemporaryDir temp;
        QVERIFY(QDir().mkpath(temp.filePath("library")) && QDir().mkpath(temp.filePath("out")));
        const QString sky = temp.filePath("library/sky.hdr");
        QVERIFY(QFile::copy(QStringLiteral(GLINT_RESOURCES_DIR "/env/studio_small_03_1k.hdr"), sky));
        MainWindow::Options options;
        options.autosaveFolder = temp.filePath("autosave");
        options.askBeforeRecovery = false;
        MainWindow window(options);
        window.resize(900, 600);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.viewport());
        RenderView& view = window.viewport()->view();
        QTRY_VERIFY_WITH_TIMEOUT(!view.stats().hint.isEmpty(), 30000); // an empty scene: nothing emits light

        // Untitled: the path stays absolute (the process's working directory means nothing here).
        QVERIFY(browseEnvironment(window, sky));
        QCOMPARE(QString::fromStdString(window.document().scene().settings.environment.file), QFileInfo(sky).absoluteFilePath());
        QVERIFY(environmentStatus(window) && environmentStatus(window)->isHidden());
        QTRY_VERIFY(view.stats().hint.isEmpty());
        const double lit = viewportBrightness(view);
        QVERIFY2(lit > 0.05, qPrintable(QString::number(lit))); // the sky, not a black image

        // The first save copies the image beside the scene; the document then names the copy.
        const QString scene = temp.filePath("out/scene.gltf");
        QVERIFY(window.saveAs(scene));
        QVERIFY(QFile::exists(temp.filePath("out/sky.hdr")));
        QCOMPARE(window.document().scene().settings.environment.file, std::string("sky.hdr"));
        QVERIFY(!window.document().isModified());
        QVERIFY2(window.document().lastWarnings().filter("environment image").isEmpty(), qPrintable(window.document().lastWarnings().join('\n')));
        QVERIFY(environmentStatus(window)->isHidden());

        // Reopened: found, no warning, the sky on screen.
        QVERIFY(window.openFile(scene));
        QCOMPARE(window.document().scene().settings.environment.file, std::string("sky.hdr"));
        QVERIFY2(window.document().lastWarnings().filter("environment image").isEmpty(), qPrintable(window.document().lastWarnings().join('\n')));
        QVERIFY(environmentStatus(window)->isHidden());
        const double reopened = viewportBrightness(view);
        QVERIFY2(reopened > 0.05, qPrintable(QString::number(reopened)));
        for (int i = 0; i < window.log().count(); ++i)
            QVERIFY2(!window.log().line(i).contains("cannot read", Qt::CaseInsensitive), qPrintable(window.log().line(i)));

        // Gone from disk: the Scene tab says so, naming the file.
        QVERIFY(QFile::remove(temp.filePath("out/sky.hdr")));
        QVERIFY(window.openFile(scene));
        QLabel* status = environmentStatus(window);
        QVERIFY(status && !status->isHidden());
        QVERIFY2(status->text().contains("sky.hdr"), qPrintable(status->text()));
    }

    // In a saved scene a file inside its folder is stored relative to it, one outside absolute.
    void chosenInASavedScene() {
        QTemporaryDir temp;
        QVERIFY(QDir().mkpath(temp.filePath("project/hdr")) && QDir().mkpath(temp.filePath("elsewhere")));
        QVERIFY(QFile::copy(QStringLiteral(GLINT_RESOURCES_DIR "/env/studio_small_03_1k.hdr"), temp.filePath("project/hdr/inside.hdr")));
        QVERIFY(QFile::copy(QStringLiteral(GLINT_RESOURCES_DIR "/env/studio_small_03_1k.hdr"), temp.filePath("elsewhere/outside.hdr")));
        MainWindow::Options options;
        options.autosaveFolder = temp.filePath("autosave");
        options.askBeforeRecovery = false;
        options.createViewport = false;
        MainWindow window(options);
        QVERIFY(window.openFile(cornellBox()));
        QVERIFY(window.saveAs(temp.filePath("project/box.gltf")));
        QVERIFY(browseEnvironment(window, temp.filePath("project/hdr/inside.hdr")));
        QCOMPARE(window.document().scene().settings.environment.file, std::string("hdr/inside.hdr"));
        QVERIFY(browseEnvironment(window, temp.filePath("elsewhere/outside.hdr")));
        QCOMPARE(QString::fromStdString(window.document().scene().settings.environment.file),
                 QFileInfo(temp.filePath("elsewhere/outside.hdr")).absoluteFilePath());
        QVERIFY(window.save());
        QVERIFY(QFile::exists(temp.filePath("project/outside.hdr")));
        QCOMPARE(window.document().scene().settings.environment.file, std::string("outside.hdr"));
        // A relative path typed into an untitled scene has no folder to resolve in: said at once.
        window.document().newScene();
        auto* path = window.sceneSettings().findChild<QLineEdit*>();
        QVERIFY(path);
        for (QLineEdit* edit : window.sceneSettings().findChildren<QLineEdit*>())
            if (edit->parentWidget() == fieldNamed<QWidget>(window.sceneSettings(), "HDR file")) path = edit;
        path->setText("sky.hdr");
        emit path->editingFinished();
        QTRY_VERIFY(environmentStatus(window) && !environmentStatus(window)->isHidden());
        QVERIFY2(environmentStatus(window)->text().contains("no folder"), qPrintable(environmentStatus(window)->text()));
    }
};

int main(int argc, char** argv) {
    glint::test::prepareGlApplication();
    QApplication app(argc, argv);
    QCoreApplication::setOrganizationName("GlintTest");
    QCoreApplication::setApplicationName("glint-environment-test");
    TestEnvironmentPath test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_environment_path.moc"
