#include "editor_app.h"

#include "main_window.h"

#include "editor/log/log_panel.h"
#include "editor/preferences/language.h"
#include "editor/preferences/preferences.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QOpenGLContext>
#include <QSurfaceFormat>

#include <cstdio>

namespace glint::editor {

bool haveDisplay() {
    return qEnvironmentVariableIsSet("DISPLAY") || qEnvironmentVariableIsSet("WAYLAND_DISPLAY") ||
           qEnvironmentVariableIsSet("QT_QPA_PLATFORM");
}

namespace {

void setGlDefaults() {
    // Must precede QApplication: contexts are shared so the viewport's GPU scene survives its
    // widget being floated or re-docked, and every context is 4.1 core like the renderer needs.
    QCoreApplication::setAttribute(Qt::AA_ShareOpenGLContexts);
    QSurfaceFormat format;
    format.setVersion(4, 1);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    QSurfaceFormat::setDefaultFormat(format);
}

// Whether this display gives the 4.1 core context the viewport needs: a remote session, the
// offscreen platform or an old driver may not, and a QOpenGLWidget without a context takes the
// whole application down at its first paint. Without one the editor opens without its viewport.
bool viewportContextAvailable() {
    QOpenGLContext context;
    context.setFormat(QSurfaceFormat::defaultFormat());
    if (!context.create()) return false;
    const QSurfaceFormat got = context.format();
    return got.profile() == QSurfaceFormat::CoreProfile && got.version() >= qMakePair(4, 1);
}

} // namespace

int runEditor(int argc, char** argv, const char* version) {
    setGlDefaults();
    QApplication app(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("Glint"));
    QCoreApplication::setApplicationName(QStringLiteral("glint"));
    QCoreApplication::setApplicationVersion(QString::fromLatin1(version));
    QGuiApplication::setApplicationDisplayName(QStringLiteral("Glint"));
    QGuiApplication::setDesktopFileName(QStringLiteral("glint"));

    Translations::of(app).install(app, Preferences::load().language);

    QCommandLineParser parser;
    parser.setApplicationDescription(QCoreApplication::translate("glint::editor::MainWindow", "Glint scene editor"));
    parser.addHelpOption();
    parser.addPositionalArgument("FILE", QCoreApplication::translate("glint::editor::MainWindow", "Scene to open"));
    parser.process(app);

    MainWindow::Options options;
    options.systemPalette = app.palette(); // the platform's, before the theme replaces it
    options.createViewport = viewportContextAvailable();
    MainWindow window(options);
    if (!options.createViewport) {
        const QString why = QCoreApplication::translate(
            "glint::editor::MainWindow",
            "This display gives no OpenGL 4.1 core context, so the editor opens without its viewport; `glint render` renders "
            "headless (EGL).");
        std::fprintf(stderr, "glint: %s\n", qPrintable(why));
        window.log().warning(why);
    }
    window.show();
    // The file asked for opens as usual; work an earlier session left unsaved is offered beside it.
    if (!parser.positionalArguments().isEmpty()) window.beginOpen(parser.positionalArguments().first());
    else window.newFromTemplate(SceneTemplate::Studio); // as File > New: something to look at and light
    window.offerRecovery();
    return app.exec();
}

} // namespace glint::editor
