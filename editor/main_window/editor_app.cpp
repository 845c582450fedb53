#include "editor_app.h"

#include "main_window.h"

#include "editor/preferences/language.h"
#include "editor/preferences/preferences.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QSurfaceFormat>

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
    MainWindow window(options);
    window.show();
    const bool recovered = window.offerRecovery();
    if (!recovered && !parser.positionalArguments().isEmpty()) window.beginOpen(parser.positionalArguments().first());
    return app.exec();
}

} // namespace glint::editor
