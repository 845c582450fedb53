// Switching the language while the editor runs (the main window under Xvfb):
// menus, actions, dock titles, panel texts, the scene settings' forms, viewport actions and an open
// export dialog change at once to German and back to English, with no restart.
#include "editor_fixtures.h"
#include "test_viewport_scene.h"

#include "editor/log/log_panel.h"
#include "editor/main_window/main_window.h"
#include "editor/outliner/outliner_panel.h"
#include "editor/preferences/language.h"
#include "editor/properties/properties_panel.h"
#include "editor/viewport/viewport.h"

#include <QAction>
#include <QApplication>
#include <QDialog>
#include <QDockWidget>
#include <QGroupBox>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QAbstractButton>
#include <QTemporaryDir>

using namespace glint::editor;

namespace {

QStringList menuTitles(MainWindow& window) {
    QStringList titles;
    for (QAction* action : window.menuBar()->actions()) titles << action->text();
    return titles;
}

QString dockTitle(MainWindow& window, const char* name) {
    auto* dock = window.findChild<QDockWidget*>(name);
    return dock ? dock->windowTitle() : QString("(no dock %1)").arg(name);
}

QStringList groupTitles(QWidget& panel) {
    QStringList titles;
    for (auto* box : panel.findChildren<QGroupBox*>()) titles << box->title();
    return titles;
}

QStringList buttonTexts(QWidget& panel) {
    QStringList texts;
    for (auto* button : panel.findChildren<QAbstractButton*>()) texts << button->text();
    return texts;
}

// Installs a language and lets the posted QEvent::LanguageChange reach every widget.
void switchTo(const QString& language) {
    QCoreApplication& app = *QCoreApplication::instance();
    QCOMPARE(Translations::of(app).install(app, language), language);
    QCoreApplication::processEvents();
    QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete); // replaced forms
}

} // namespace

class TestLanguageSwitch : public QObject {
    Q_OBJECT
private slots:
    void switchesToGermanAndBack() {
        QTemporaryDir temp;
        QVERIFY(temp.isValid());
        MainWindow::Options options;
        options.autosaveFolder = temp.filePath("autosave");
        options.askBeforeRecovery = false;
        MainWindow window(options);
        window.show();
        QVERIFY(window.openFile(test::cornellBox()));
        auto* save = window.findChild<QAction*>("file.save");
        QVERIFY(save);
        // A dialog open at the time, and the viewport's actions.
        window.findChild<QAction*>("file.export_still")->trigger();
        auto* exportDialog = window.findChild<QDialog*>();
        QVERIFY(exportDialog);
        QVERIFY(window.viewport());
        QAction* frameSelection = window.viewport()->frameSelectionAction();
        auto english = [&] {
            QVERIFY2(menuTitles(window).mid(0, 2) == QStringList({"&File", "&Edit"}), qPrintable(menuTitles(window).join(',')));
            QCOMPARE(save->text(), QString("&Save"));
            QCOMPARE(dockTitle(window, "OutlinerDock"), QString("Outliner"));
            QCOMPARE(window.outliner().filter().placeholderText(), QString("Filter by name"));
            QVERIFY2(groupTitles(window.sceneSettings()).contains("Render settings"), qPrintable(groupTitles(window.sceneSettings()).join(',')));
            QVERIFY(buttonTexts(window.log()).contains("Clear"));
            QVERIFY(buttonTexts(window.outliner()).contains("Add"));
            QCOMPARE(exportDialog->windowTitle(), QString("Export image"));
            QVERIFY(buttonTexts(*exportDialog).contains("Export"));
            QCOMPARE(frameSelection->text(), QString("Frame selection"));
        };
        english();

        switchTo("de");
        QVERIFY2(menuTitles(window).value(0) == "&Datei", qPrintable(menuTitles(window).join(',')));
        QCOMPARE(save->text(), QString("&Speichern"));
        QCOMPARE(dockTitle(window, "OutlinerDock"), QString("Gliederung"));
        QCOMPARE(dockTitle(window, "SceneDock"), QString("Szene"));
        QCOMPARE(window.outliner().filter().placeholderText(), QString("Nach Name filtern"));
        QVERIFY(buttonTexts(window.outliner()).contains(QString("Hinzufügen")));
        QVERIFY2(groupTitles(window.sceneSettings()).contains(QString("Render-Einstellungen")),
                 qPrintable(groupTitles(window.sceneSettings()).join(',')));
        QVERIFY(buttonTexts(window.log()).contains("Leeren"));
        QCOMPARE(exportDialog->windowTitle(), QString("Bild exportieren"));
        QVERIFY2(buttonTexts(*exportDialog).contains("Exportieren"), qPrintable(buttonTexts(*exportDialog).join(',')));
        QCOMPARE(frameSelection->text(), QString("Auswahl einpassen"));
        // The document is untouched by a language change.
        QVERIFY(!window.document().isModified());

        switchTo("en");
        english();
    }
};

int main(int argc, char** argv) {
    glint::test::prepareGlApplication(); // the viewport's QOpenGLWidget
    QApplication app(argc, argv);
    TestLanguageSwitch test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_language_switch.moc"
