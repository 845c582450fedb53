// The main window's actions, menus and toolbar.
#include "main_window.h"

#include "recent_files.h"
#include "theme.h"

#include "editor/document/document.h"
#include "editor/document/edit_operations.h"
#include "editor/export/export_dialog.h"
#include "editor/history_view/command_labels.h"
#include "editor/outliner/outliner_panel.h"
#include "editor/preferences/language.h"
#include "editor/preferences/preferences_dialog.h"
#include "editor/preferences/retranslate.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>
#include <QStyle>
#include <QToolBar>

#include <exception>

namespace glint::editor {
namespace {

// A menu whose title follows the language (retranslate.h).
QMenu* keptMenu(QMenu* menu, const char* title) {
    keepTranslated(menu, TextRole::Title, MainWindow::staticMetaObject.className(), title);
    return menu;
}

} // namespace

QAction* MainWindow::makeAction(const QString& name, const char* text, const QKeySequence& shortcut) {
    auto* action = new QAction(this);
    keepTranslated(action, TextRole::Text, staticMetaObject.className(), text);
    action->setObjectName(name);
    action->setShortcut(shortcut);
    action->setShortcutContext(Qt::WindowShortcut);
    addAction(action); // shortcuts work even when the menu bar is hidden
    actions_ << action;
    return action;
}

QList<QAction*> MainWindow::keymapActions() const { return actions_ + viewportActions_; }

void MainWindow::createActions() {
    QStyle* s = style();
    auto* newScene = makeAction("file.new", QT_TR_NOOP("&New"), QKeySequence::New); // the Studio template
    connect(newScene, &QAction::triggered, this, [this] { newFromTemplate(SceneTemplate::Studio); });
    for (const SceneTemplate kind : kSceneTemplates) {
        QAction* action = makeAction(templateActionId(kind), templateTitle(kind), {});
        keepTranslated(action, TextRole::Text, "glint::editor::SceneTemplates", templateTitle(kind));
        connect(action, &QAction::triggered, this, [this, kind] { newFromTemplate(kind); });
        templateActions_ << action;
    }
    auto* open = makeAction("file.open", QT_TR_NOOP("&Open..."), QKeySequence::Open);
    open->setIcon(s->standardIcon(QStyle::SP_DialogOpenButton));
    connect(open, &QAction::triggered, this, [this] {
        if (!maybeSave()) return;
        const QString path = QFileDialog::getOpenFileName(this, tr("Open scene"), {},
                                                          tr("Scenes (*.gltf *.glb *.glint.json);;All files (*)"));
        if (!path.isEmpty()) beginOpen(path);
    });
    auto* import = import_ = makeAction("file.import", QT_TR_NOOP("&Import..."), QKeySequence(Qt::CTRL | Qt::Key_I));
    connect(import, &QAction::triggered, this, [this] {
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Import into the scene"), {},
            tr("Scenes and models (*.gltf *.glb *.obj *.ply *.stl *.fbx *.dae *.3ds);;All files (*)"));
        if (!path.isEmpty()) beginImport(path);
    });
    auto* saveAction = makeAction("file.save", QT_TR_NOOP("&Save"), QKeySequence::Save);
    saveAction->setIcon(s->standardIcon(QStyle::SP_DialogSaveButton));
    connect(saveAction, &QAction::triggered, this, [this] { save(); });
    // Explicit keys where the platform's standard key may be empty (Save As, Preferences).
    auto* saveAsAction = makeAction("file.save_as", QT_TR_NOOP("Save &As..."), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S));
    connect(saveAsAction, &QAction::triggered, this, [this] { saveAs(); });
    auto* prefs = makeAction("edit.preferences", QT_TR_NOOP("&Preferences..."), QKeySequence(Qt::CTRL | Qt::Key_Comma));
    connect(prefs, &QAction::triggered, this, &MainWindow::showPreferences);
    auto* quit = makeAction("file.quit", QT_TR_NOOP("&Quit"), QKeySequence::Quit);
    connect(quit, &QAction::triggered, this, &QWidget::close);

    undo_ = makeAction("edit.undo", QT_TR_NOOP("&Undo"), QKeySequence::Undo);
    undo_->setIcon(s->standardIcon(QStyle::SP_ArrowBack));
    connect(undo_, &QAction::triggered, this, [this] {
        try {
            document_->undo();
        } catch (const std::exception& e) {
            report(QString::fromStdString(e.what()));
        }
    });
    redo_ = makeAction("edit.redo", QT_TR_NOOP("&Redo"), QKeySequence::Redo);
    redo_->setIcon(s->standardIcon(QStyle::SP_ArrowForward));
    connect(redo_, &QAction::triggered, this, [this] {
        try {
            document_->redo();
        } catch (const std::exception& e) {
            report(QString::fromStdString(e.what()));
        }
    });
    delete_ = makeAction("edit.delete", QT_TR_NOOP("&Delete"), QKeySequence::Delete);
    connect(delete_, &QAction::triggered, this, [this] {
        const QString error = deleteSelection(*document_);
        if (!error.isEmpty()) statusBar()->showMessage(error, 4000);
    });
    duplicate_ = makeAction("edit.duplicate", QT_TR_NOOP("D&uplicate"), QKeySequence(Qt::CTRL | Qt::Key_D));
    connect(duplicate_, &QAction::triggered, this, [this] {
        const QString error = duplicateSelection(*document_);
        if (!error.isEmpty()) statusBar()->showMessage(error, 4000);
    });
    auto* selectAll = makeAction("edit.select_all", QT_TR_NOOP("Select &All"), QKeySequence::SelectAll);
    connect(selectAll, &QAction::triggered, this, [this] { document_->setSelection(document_->scene().depthFirst()); });
    auto* selectNone = makeAction("edit.select_none", QT_TR_NOOP("Select &None"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_A));
    connect(selectNone, &QAction::triggered, this, [this] { document_->setSelection({}); });
}

void MainWindow::createMenus() {
    QMenu* file = keptMenu(menuBar()->addMenu(QString()), QT_TR_NOOP("&File"));
    auto find = [this](const char* name) { return findChild<QAction*>(name, Qt::FindDirectChildrenOnly); };
    file->addAction(find("file.new"));
    QMenu* fromTemplate = keptMenu(file->addMenu(QString()), QT_TR_NOOP("New from &template"));
    fromTemplate->addActions(templateActions_);
    file->addAction(find("file.open"));
    recentMenu_ = keptMenu(file->addMenu(QString()), QT_TR_NOOP("Open &Recent"));
    rebuildRecentMenu();
    recoverMenu_ = keptMenu(file->addMenu(QString()), QT_TR_NOOP("Re&cover"));
    recoverMenu_->setObjectName("file.recover");
    refreshRecovery();
    file->addAction(find("file.import"));
    file->addSeparator();
    file->addAction(find("file.save"));
    file->addAction(find("file.save_as"));
    createExportActions(file);
    file->addSeparator();
    file->addAction(find("file.quit"));

    QMenu* edit = keptMenu(menuBar()->addMenu(QString()), QT_TR_NOOP("&Edit"));
    edit->addAction(undo_);
    edit->addAction(redo_);
    edit->addSeparator();
    edit->addAction(duplicate_);
    edit->addAction(delete_);
    edit->addSeparator();
    edit->addAction(find("edit.select_all"));
    edit->addAction(find("edit.select_none"));
    edit->addSeparator();
    edit->addAction(find("edit.preferences"));

    menuBar()->addMenu(outliner_->addMenu());

    viewMenu_ = keptMenu(menuBar()->addMenu(QString()), QT_TR_NOOP("&View"));
    for (QAction* action : viewportActions_) viewMenu_->addAction(action);
    if (!viewportActions_.isEmpty()) viewMenu_->addSeparator();
    QMenu* panels = keptMenu(viewMenu_->addMenu(QString()), QT_TR_NOOP("&Panels"));
    for (QDockWidget* dock : findChildren<QDockWidget*>()) panels->addAction(dock->toggleViewAction());
    QMenu* theme = keptMenu(viewMenu_->addMenu(QString()), QT_TR_NOOP("&Theme"));
    auto* themes = new QActionGroup(this);
    for (const auto& [value, label] : {std::pair{Theme::System, QT_TR_NOOP("System")}, std::pair{Theme::Light, QT_TR_NOOP("Light")},
                                       std::pair{Theme::Dark, QT_TR_NOOP("Dark")}}) {
        QAction* action = theme->addAction(QString());
        keepTranslated(action, TextRole::Text, staticMetaObject.className(), label);
        action->setCheckable(true);
        action->setChecked(themeFromName(preferences_.theme) == value);
        themes->addAction(action);
        connect(action, &QAction::triggered, this, [this, value = value] {
            preferences_.theme = themeName(value);
            preferences_.save();
            applyPreferences();
        });
    }

    QMenu* help = keptMenu(menuBar()->addMenu(QString()), QT_TR_NOOP("&Help"));
    QAction* about = help->addAction(QString(), this, [this] {
        QMessageBox::about(this, tr("About Glint"),
                           tr("Glint %1: a scene editor with a built-in OpenGL 4.1 path tracer.")
                               .arg(QCoreApplication::applicationVersion()));
    });
    keepTranslated(about, TextRole::Text, staticMetaObject.className(), QT_TR_NOOP("&About Glint"));
    QAction* aboutQt = help->addAction(QString(), qApp, &QApplication::aboutQt);
    keepTranslated(aboutQt, TextRole::Text, staticMetaObject.className(), QT_TR_NOOP("About &Qt"));
}

void MainWindow::createExportActions(QMenu* file) {
    file->addSeparator();
    auto* still = makeAction("file.export_still", QT_TR_NOOP("Export &Image..."), QKeySequence(Qt::CTRL | Qt::Key_E));
    auto* animation = makeAction("file.export_animation", QT_TR_NOOP("Export A&nimation..."),
                                 QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_E));
    auto open = [this](ExportDialog::Kind kind) {
        // Modeless: the export runs in the background while the dialog shows its progress.
        auto* dialog = new ExportDialog(*document_, kind, viewport_, this);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->show();
    };
    connect(still, &QAction::triggered, this, [open] { open(ExportDialog::Kind::Still); });
    connect(animation, &QAction::triggered, this, [open] { open(ExportDialog::Kind::Animation); });
    file->addAction(still);
    file->addAction(animation);
}

void MainWindow::createToolBar() {
    QToolBar* bar = addToolBar(QString());
    bar->setObjectName("MainToolBar");
    keepTranslated(bar, TextRole::Title, staticMetaObject.className(), QT_TR_NOOP("Main"));
    keepTranslated(bar, TextRole::AccessibleName, staticMetaObject.className(), QT_TR_NOOP("Main toolbar"));
    auto find = [this](const char* name) { return findChild<QAction*>(name, Qt::FindDirectChildrenOnly); };
    bar->addAction(find("file.open"));
    bar->addAction(find("file.save"));
    bar->addSeparator();
    bar->addAction(undo_);
    bar->addAction(redo_);
    if (!viewportActions_.isEmpty()) {
        QToolBar* view = addToolBar(QString());
        view->setObjectName("ViewToolBar");
        keepTranslated(view, TextRole::Title, staticMetaObject.className(), QT_TR_NOOP("View"));
        keepTranslated(view, TextRole::AccessibleName, staticMetaObject.className(), QT_TR_NOOP("View toolbar"));
        view->addActions(viewportActions_);
    }
}

void MainWindow::rebuildRecentMenu() {
    recentMenu_->clear();
    const QStringList files = RecentFiles().list();
    for (const QString& path : files) {
        recentMenu_->addAction(QFileInfo(path).fileName(), this, [this, path] {
            if (maybeSave()) beginOpen(path);
        })->setToolTip(path);
    }
    if (!files.isEmpty()) recentMenu_->addSeparator();
    QAction* clear = recentMenu_->addAction(tr("Clear the list"), this, [this] {
        RecentFiles().clear();
        rebuildRecentMenu();
    });
    clear->setEnabled(!files.isEmpty());
}

void MainWindow::updateUndoActions() {
    const History& history = document_->history();
    undo_->setEnabled(history.canUndo());
    redo_->setEnabled(history.canRedo());
    undo_->setText(history.canUndo() ? tr("&Undo %1").arg(commandLabel(history.label(history.index() - 1))) : tr("&Undo"));
    redo_->setText(history.canRedo() ? tr("&Redo %1").arg(commandLabel(history.label(history.index()))) : tr("&Redo"));
    const bool selected = !document_->selection().empty();
    delete_->setEnabled(selected);
    duplicate_->setEnabled(selected);
}

void MainWindow::showPreferences() {
    PreferencesDialog dialog(preferences_, keymapActions(), defaultShortcuts_, this);
    if (dialog.exec() != QDialog::Accepted) return;
    const QString oldLanguage = preferences_.language;
    preferences_ = dialog.result();
    preferences_.save();
    applyPreferences();
    if (preferences_.language != oldLanguage) { // every widget follows through QEvent::LanguageChange
        QCoreApplication& app = *QCoreApplication::instance();
        Translations::of(app).install(app, preferences_.language);
    }
}

} // namespace glint::editor
