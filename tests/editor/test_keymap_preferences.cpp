// Edit > Preferences driven as a person does it, in the real main window under Xvfb: rebinding one
// viewport action leaves every other shortcut alone and survives a restart; OK after a language
// change is accepted in both directions; the keymap lists actions by their own names; Qt's own
// strings, the viewport's texts and the view modes follow the language; W/E/R and G/S switch the
// gizmo from anywhere in the window.
#include "editor_fixtures.h"
#include "window_options.h"
#include "test_viewport_scene.h"

#include "editor/document/edit_operations.h"
#include "editor/main_window/main_window.h"
#include "editor/outliner/outliner_panel.h"
#include "editor/properties/properties_panel.h"
#include "editor/preferences/language.h"
#include "editor/preferences/preferences.h"
#include "editor/preferences/preferences_dialog.h"
#include "editor/viewport/render_view.h"
#include "editor/viewport/viewport.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QKeySequenceEdit>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTimer>
#include <QToolButton>
#include <QTreeView>

#include <functional>

using namespace glint;
using namespace glint::editor;

namespace {

using Shortcuts = QMap<QString, QList<QKeySequence>>;

Shortcuts shortcutsOf(const MainWindow& window) {
    Shortcuts all;
    for (QAction* action : window.keymapActions()) all[action->objectName()] = action->shortcuts();
    return all;
}

QAction* actionNamed(const MainWindow& window, const QString& id) {
    for (QAction* action : window.keymapActions())
        if (action->objectName() == id) return action;
    return nullptr;
}

// What one run of the preferences dialog saw: its keymap names, and any message box it raised.
struct DialogRun {
    QStringList keymapNames;
    QString refusal; // the text of a message box that came up after OK (a conflict), or empty
    bool accepted = false;
};

// Opens Edit > Preferences, lets `drive` change it, presses OK. A message box raised by OK is
// recorded and closed, and the dialog is then cancelled, so a refusal fails the test instead of
// hanging it.
DialogRun runPreferences(MainWindow& window, const std::function<void(PreferencesDialog&)>& drive) {
    DialogRun run;
    QTimer poll;
    poll.setInterval(20);
    bool okPressed = false;
    QObject::connect(&poll, &QTimer::timeout, [&] {
        QWidget* modal = QApplication::activeModalWidget();
        if (auto* box = qobject_cast<QMessageBox*>(modal)) {
            run.refusal = box->text();
            box->reject();
            return;
        }
        auto* dialog = qobject_cast<PreferencesDialog*>(modal);
        if (!dialog) return;
        if (okPressed) { // OK did not close it
            dialog->reject();
            return;
        }
        auto* table = dialog->findChild<QTableWidget*>();
        for (int row = 0; table && row < table->rowCount(); ++row) run.keymapNames << table->item(row, 0)->text();
        drive(*dialog);
        okPressed = true;
        auto* buttons = dialog->findChild<QDialogButtonBox*>();
        QTest::mouseClick(buttons->button(QDialogButtonBox::Ok), Qt::LeftButton);
    });
    poll.start();
    window.showPreferences(); // modal: returns once the dialog closed
    poll.stop();
    run.accepted = okPressed && run.refusal.isEmpty();
    return run;
}

QKeySequenceEdit* shortcutEdit(PreferencesDialog& dialog, const QString& command) {
    return glint::editor::test::fieldNamed<QKeySequenceEdit>(dialog, PreferencesDialog::tr("Shortcut for %1").arg(command));
}

void chooseLanguage(PreferencesDialog& dialog, const QString& code) {
    auto* language = glint::editor::test::fieldNamed<QComboBox>(dialog, PreferencesDialog::tr("Language"));
    QVERIFY(language);
    language->setCurrentIndex(language->findData(code));
}


// Gives the viewport's render view the keyboard focus in an active window (shortcuts need both).
void focusView(MainWindow& window) {
    window.show();
    window.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&window));
    window.viewport()->view().setFocus();
    QTRY_VERIFY(window.viewport()->view().hasFocus());
}

} // namespace

class TestKeymapPreferences : public QObject {
    Q_OBJECT
private slots:
    void init() {
        QSettings().clear();
        QCoreApplication& app = *QCoreApplication::instance();
        Translations::of(app).install(app, "en");
    }

    // Issue 17, item 1: Normals on N; every other action keeps its shortcut, also after a restart.
    void rebindingOneViewportActionKeepsTheOthersAcrossARestart() {
        QTemporaryDir temp;
        Shortcuts defaults;
        {
            MainWindow window(glint::editor::test::windowOptions(temp.filePath("a")));
            focusView(window);
            defaults = shortcutsOf(window);
            QCOMPARE(defaults.value("view.mode.normals").value(0), QKeySequence(Qt::Key_4));
            const DialogRun run = runPreferences(window, [](PreferencesDialog& dialog) {
                QKeySequenceEdit* normals = shortcutEdit(dialog, "Normals");
                QVERIFY(normals);
                normals->setKeySequence(QKeySequence(Qt::Key_N));
            });
            QVERIFY2(run.accepted, qPrintable(run.refusal));
            Shortcuts expected = defaults;
            expected["view.mode.normals"] = {QKeySequence(Qt::Key_N)};
            QCOMPARE(shortcutsOf(window), expected);
            // Saved: only the one binding that differs from the defaults.
            QSettings settings;
            settings.beginGroup("keymap");
            QCOMPARE(settings.childKeys(), QStringList{"view.mode.normals"});
            QCOMPARE(settings.value("view.mode.normals").toString(), QString("N"));
            settings.endGroup();
            focusView(window);
            QTest::keyClick(&window.viewport()->view(), Qt::Key_N);
            QCOMPARE(window.viewport()->view().mode(), ViewMode::Normals);
        }
        MainWindow restarted(glint::editor::test::windowOptions(temp.filePath("b")));
        Shortcuts expected = defaults;
        expected["view.mode.normals"] = {QKeySequence(Qt::Key_N)};
        QCOMPARE(shortcutsOf(restarted), expected);
        focusView(restarted);
        RenderView& view = restarted.viewport()->view();
        QTest::keyClick(&view, Qt::Key_2);
        QCOMPARE(view.mode(), ViewMode::Solid);
        QTest::keyClick(&view, Qt::Key_N);
        QCOMPARE(view.mode(), ViewMode::Normals);
        QTest::keyClick(&view, Qt::Key_3);
        QCOMPARE(view.mode(), ViewMode::Wireframe);
        QTest::keyClick(&view, Qt::Key_4); // no longer bound
        QCOMPARE(view.mode(), ViewMode::Wireframe);
        // Back to the defaults: nothing stays in the settings.
        const DialogRun reset = runPreferences(restarted, [](PreferencesDialog& dialog) {
            for (QPushButton* button : dialog.findChildren<QPushButton*>())
                if (button->text() == PreferencesDialog::tr("Reset all to defaults")) button->click();
        });
        QVERIFY2(reset.accepted, qPrintable(reset.refusal));
        QCOMPARE(shortcutsOf(restarted), defaults);
        QSettings settings;
        settings.beginGroup("keymap");
        QVERIFY2(settings.childKeys().isEmpty(), qPrintable(settings.childKeys().join(',')));
    }

    // Issue 17, item 2: OK after a live switch to German and back; names and Qt's strings follow.
    void okAfterALanguageChangeInBothDirections() {
        QTemporaryDir temp;
        MainWindow window(glint::editor::test::windowOptions(temp.filePath("c")));
        focusView(window);
        window.document().newScene(); // nothing emits light: the viewport says so
        RenderView& view = window.viewport()->view();
        QTRY_VERIFY_WITH_TIMEOUT(view.stats().hint.startsWith("Nothing in the scene emits light"), 30000);
        // The Undo action's text names the step ("Undo Add ball"); the keymap must not.
        QCOMPARE(addNode(window.document(), "ball", defaultShape(ShapeKind::Sphere)), QString());
        QVERIFY(actionNamed(window, "edit.undo")->text().contains("ball"));
        const Shortcuts defaults = shortcutsOf(window);

        const DialogRun toGerman = runPreferences(window, [](PreferencesDialog& dialog) { chooseLanguage(dialog, "de"); });
        QVERIFY2(toGerman.accepted, qPrintable(toGerman.refusal));
        QVERIFY(toGerman.keymapNames.contains("Undo"));
        QVERIFY2(toGerman.keymapNames.filter("ball").isEmpty(), qPrintable(toGerman.keymapNames.join(',')));
        QCoreApplication::processEvents();
        QCOMPARE(window.menuBar()->actions().value(0)->text(), QString("&Datei"));
        QCOMPARE(shortcutsOf(window), defaults);
        // The view modes and tools by the names German users know (Blender's German interface).
        QCOMPARE(actionNamed(window, "view.mode.solid")->text(), QString("Solid"));
        QCOMPARE(actionNamed(window, "view.gizmo.rotate")->text(), QString("Drehen"));
        // Qt's own strings (qtbase_de.qm, Debian package qt6-translations-l10n).
        QVERIFY2(QKeySequence(QKeySequence::Delete).toString(QKeySequence::NativeText) == "Entf",
                 "Qt's German translations are missing: install qt6-translations-l10n");

        const DialogRun toEnglish = runPreferences(window, [](PreferencesDialog& dialog) {
            // Qt's own texts in the dialog are German too.
            QKeySequenceEdit* edit = dialog.findChild<QKeySequenceEdit*>();
            QVERIFY(edit);
            QLineEdit* line = edit->findChild<QLineEdit*>();
            QVERIFY(line);
            QVERIFY2(line->placeholderText() != "Press shortcut", qPrintable(line->placeholderText()));
            chooseLanguage(dialog, "en");
        });
        QVERIFY2(toEnglish.accepted, qPrintable(toEnglish.refusal));
        // Named after the action, not after the step it would redo or undo now.
        QVERIFY(toEnglish.keymapNames.contains(QString("Rückgängig")));
        QVERIFY2(toEnglish.keymapNames.filter("ball").isEmpty(), qPrintable(toEnglish.keymapNames.join(',')));
        QCoreApplication::processEvents();
        QCOMPARE(window.menuBar()->actions().value(0)->text(), QString("&File"));
        QCOMPARE(shortcutsOf(window), defaults);
        QTRY_VERIFY2(view.stats().hint.startsWith("Nothing in the scene emits light"), qPrintable(view.stats().hint));
        QVERIFY(QSettings().value("ui/language").toString() == "en");
    }

    // Issue 12: the viewport's sample cap is a field of the Scene panel as well as of the
    // preferences, one setting for both; the view stops there, and the panel's Pause button pauses it.
    void viewportSamplesInTheScenePanel() {
        QTemporaryDir temp;
        MainWindow window(glint::editor::test::windowOptions(temp.filePath("d")));
        focusView(window);
        auto* samples = glint::editor::test::fieldNamed<QSpinBox>(window.sceneSettings(), "Viewport samples");
        QVERIFY(samples);
        QCOMPARE(samples->value(), Preferences{}.viewportSamples);
        samples->setValue(4);
        RenderView& view = window.viewport()->view();
        QCOMPARE(view.sampleCap(), 4);
        QCOMPARE(QSettings().value("viewport/samples").toInt(), 4);
        QTRY_VERIFY_WITH_TIMEOUT(view.stats().stage == ViewStage::Converged, 60000);
        QCOMPARE(view.stats().samples, 4);
        // Changed in the preferences: the panel shows it.
        const DialogRun run = runPreferences(window, [](PreferencesDialog& dialog) {
            auto* field = glint::editor::test::fieldNamed<QSpinBox>(dialog, PreferencesDialog::tr("Viewport samples"));
            QVERIFY(field);
            QCOMPARE(field->value(), 4);
            field->setValue(0);
        });
        QVERIFY2(run.accepted, qPrintable(run.refusal));
        QCOMPARE(samples->value(), 0);
        QCOMPARE(samples->text(), QString("No limit"));
        QCOMPARE(view.sampleCap(), 0);
        QTRY_VERIFY_WITH_TIMEOUT(view.stats().samples > 4, 60000); // no cap: it goes on
        QToolButton* pause = nullptr;
        for (auto* button : window.sceneSettings().findChildren<QToolButton*>())
            if (button->defaultAction() == window.viewport()->pauseAction()) pause = button;
        QVERIFY(pause);
        pause->click();
        QVERIFY(view.paused());
        QTRY_VERIFY_WITH_TIMEOUT(view.stats().stage == ViewStage::Paused, 30000);
        const int pausedAt = view.stats().samples;
        for (int i = 0; i < 2; ++i) { // paints while paused add no sample
            const long long paints = view.stats().paints;
            view.update();
            QTRY_VERIFY(view.stats().paints > paints);
        }
        QCOMPARE(view.stats().samples, pausedAt);
        pause->click();
        QVERIFY(!view.paused());
    }

    // A keymap saved before version 2 held every action, empty ones too: those are not bindings.
    void keymapOfEarlierVersionsKeepsOnlyBindings() {
        QSettings settings;
        settings.setValue("keymap/view.gizmo.rotate", "");
        settings.setValue("keymap/view.mode.normals", "N");
        QTemporaryDir temp;
        MainWindow window(glint::editor::test::windowOptions(temp.filePath("e")));
        QCOMPARE(actionNamed(window, "view.gizmo.rotate")->shortcut(), QKeySequence(Qt::Key_E));
        QCOMPARE(actionNamed(window, "view.mode.normals")->shortcut(), QKeySequence(Qt::Key_N));
    }

    // W/E/R switch the gizmo wherever the focus is (not in a text field), G and S too.
    void gizmoKeysWorkFromAnyPanel() {
        QTemporaryDir temp;
        MainWindow window(glint::editor::test::windowOptions(temp.filePath("d")));
        focusView(window);
        RenderView& view = window.viewport()->view();
        QTreeView& outliner = window.outliner().view();
        outliner.setFocus();
        QTRY_VERIFY(outliner.hasFocus());
        QTest::keyClick(&outliner, Qt::Key_E);
        QCOMPARE(view.gizmoMode(), GizmoMode::Rotate);
        QTest::keyClick(&outliner, Qt::Key_R);
        QCOMPARE(view.gizmoMode(), GizmoMode::Scale);
        QTest::keyClick(&outliner, Qt::Key_W);
        QCOMPARE(view.gizmoMode(), GizmoMode::Translate);
        QTest::keyClick(&outliner, Qt::Key_S);
        QCOMPARE(view.gizmoMode(), GizmoMode::Scale);
        QTest::keyClick(&outliner, Qt::Key_G);
        QCOMPARE(view.gizmoMode(), GizmoMode::Translate);
        view.setFocus();
        QTRY_VERIFY(view.hasFocus());
        QTest::keyClick(&view, Qt::Key_E);
        QCOMPARE(view.gizmoMode(), GizmoMode::Rotate);
        // Typing in a text field types.
        QLineEdit* filter = &window.outliner().filter();
        filter->setFocus();
        QTRY_VERIFY(filter->hasFocus());
        QTest::keyClicks(filter, "sw");
        QCOMPARE(filter->text(), QString("sw"));
        QCOMPARE(view.gizmoMode(), GizmoMode::Rotate);
        // While the view flies (right drag), W and S move the camera: the gizmo stays as it is.
        view.setFocus();
        QTRY_VERIFY(view.hasFocus());
        const QPoint middle = view.rect().center();
        QTest::mousePress(&view, Qt::RightButton, Qt::NoModifier, middle);
        QCOMPARE(view.tools().tool(), Tool::Fly);
        QTest::keyPress(&view, Qt::Key_S);
        QTest::keyRelease(&view, Qt::Key_S);
        QCOMPARE(view.gizmoMode(), GizmoMode::Rotate);
        QTest::mouseRelease(&view, Qt::RightButton, Qt::NoModifier, middle);
        QTest::keyClick(&view, Qt::Key_S);
        QCOMPARE(view.gizmoMode(), GizmoMode::Scale);
        // Save As on Ctrl+Shift+S, as everywhere else.
        QCOMPARE(actionNamed(window, "file.save_as")->shortcut(), QKeySequence("Ctrl+Shift+S"));
    }
};

int main(int argc, char** argv) {
    glint::test::prepareGlApplication();
    QApplication app(argc, argv);
    QCoreApplication::setOrganizationName("GlintTest");
    QCoreApplication::setApplicationName("glint-keymap-test");
    TestKeymapPreferences test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_keymap_preferences.moc"
