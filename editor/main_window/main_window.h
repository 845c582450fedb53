#pragma once
// The editor's main window: the viewport in the middle, dockable panels around it (outliner,
// properties, scene settings, undo history, log), menus, a toolbar and a status bar. The window
// owns the Document; every panel edits it through commands and follows its signals.
#include "autosave.h"

#include "editor/document/document.h"
#include "editor/document/scene_templates.h"
#include "editor/preferences/preferences.h"

#include <QKeySequence>
#include <QMainWindow>
#include <QMap>
#include <QPalette>
#include <QUrl>

#include <optional>

class QAction;
class QDockWidget;
class QLabel;
class QMenu;

namespace glint::editor {

class HistoryPanel;
class LoadProgress;
class LogPanel;
class MaterialsPanel;
class OutlinerPanel;
class PropertiesPanel;
class RecoveryBar;
class TimelinePanel;
class Viewport;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    struct Options {
        QString autosaveFolder;      // empty: the standard place
        bool askBeforeRecovery = true; // false: offerRecovery() recovers the newest copy at once (tests)
        QPalette systemPalette;
        bool createViewport = true;    // false: a placeholder (tests of the panels alone)
    };
    explicit MainWindow(Options options, QWidget* parent = nullptr);
    ~MainWindow() override;

    Document& document() { return *document_; }
    OutlinerPanel& outliner() { return *outliner_; }
    PropertiesPanel& properties() { return *properties_; }
    PropertiesPanel& sceneSettings() { return *sceneSettings_; }
    HistoryPanel& historyPanel() { return *history_; }
    LogPanel& log() { return *log_; }
    MaterialsPanel& materials() { return *materials_; }
    Autosave& autosave() { return *autosave_; }
    QWidget* centralView() const { return centralWidget(); }
    Viewport* viewport() const { return viewport_; } // null without the viewport
    TimelinePanel* timeline() const { return timeline_; }

    // Every action with a shortcut the keymap may change, and their default shortcuts by object
    // name (the keymap in the preferences stores only what differs from these).
    QList<QAction*> keymapActions() const;
    const QMap<QString, QList<QKeySequence>>& defaultShortcuts() const { return defaultShortcuts_; }
    // Opens Edit > Preferences (modal) and applies what it returns.
    void showPreferences();

    // Reads the file in the background (Document::startOpen): the window stays usable, the status
    // bar shows progress with a Cancel button, and the outcome is reported when it arrives
    // (failures in the log and a message box). Every way of opening a file goes through these.
    void beginOpen(const QString& path);
    void beginImport(const QString& path);
    // The same open, reading on the calling thread and reporting alike; returns whether it worked
    // (tests that need the document at once).
    bool openFile(const QString& path);
    bool save();
    bool saveAs(const QString& path = {});
    // Offers the copies earlier sessions left behind (they crashed or were killed) in a bar over
    // the viewport and in File > Recover, never in a modal dialog: the file asked for opens as
    // usual. Returns whether a recovery started (only without askBeforeRecovery).
    bool offerRecovery();
    // Reads `leftover` in the background in place of the document (after the unsaved-changes
    // prompt); returns whether it started.
    bool recover(const Autosave::Leftover& leftover);
    RecoveryBar& recoveryBar() { return *recoveryBar_; }
    LoadProgress& loadProgress() { return *loadProgress_; }
    // What dropping files does: a scene file replaces the document (after asking about unsaved
    // changes); with `merge`, or for formats Glint only imports, files are merged into it.
    // The node under a drop at `windowPos` in the viewport that can take a material (none elsewhere).
    NodeId materialDropTarget(QPoint windowPos);
    void openDropped(const QList<QUrl>& urls, bool merge);
    // Asks about unsaved changes; false when the user cancels.
    bool maybeSave();
    // File > New (Studio) and File > New from template: after asking about unsaved changes.
    void newFromTemplate(SceneTemplate kind);

protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dragMoveEvent(QDragMoveEvent* event) override;
    void dropEvent(QDropEvent* event) override;
    void changeEvent(QEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void createCentralView();
    void createViewport();
    void createDocks();
    QDockWidget* addDock(QWidget* widget, const char* title, const QString& name, Qt::DockWidgetArea area);
    void createActions();
    void createMenus();
    void createToolBar();
    void createStatusBar();
    void createExportActions(QMenu* file);
    void applyPreferences();
    void rememberDefaultShortcuts();
    void restoreLayout();
    void fitToScreen();
    void fitDocks();
    void saveLayout();
    void updateTitle();
    void updateStatus();
    void updateUndoActions();
    void rebuildRecentMenu();
    void report(const QString& message);
    void connectLoading();
    void onLoadStarted(Document::LoadKind kind, const QString& path);
    void onLoaded(Document::LoadKind kind, const QString& path);
    void onLoadFailed(Document::LoadKind kind, const QString& path, const QString& message);
    void onLoadCancelled(Document::LoadKind kind, const QString& path);
    void updateLoadActions();
    void refreshRecovery();
    // `text` is the untranslated source (QT_TR_NOOP): the action follows language changes.
    QAction* makeAction(const QString& name, const char* text, const QKeySequence& shortcut = {});
    void retranslate(); // after a language change: kept texts, then the ones built from data

    Options options_;
    Document* document_ = nullptr;
    Autosave* autosave_ = nullptr;
    OutlinerPanel* outliner_ = nullptr;
    PropertiesPanel* properties_ = nullptr;
    PropertiesPanel* sceneSettings_ = nullptr;
    HistoryPanel* history_ = nullptr;
    LogPanel* log_ = nullptr;
    Viewport* viewport_ = nullptr;
    TimelinePanel* timeline_ = nullptr;
    MaterialsPanel* materials_ = nullptr;
    QMenu* recentMenu_ = nullptr;
    QMenu* recoverMenu_ = nullptr;
    RecoveryBar* recoveryBar_ = nullptr;
    std::optional<Autosave::Leftover> recovering_; // the copy being read
    bool recoveryDismissed_ = false;
    QMenu* viewMenu_ = nullptr;
    QLabel* selectionLabel_ = nullptr;
    QLabel* sceneLabel_ = nullptr;
    QLabel* renderLabel_ = nullptr;
    LoadProgress* loadProgress_ = nullptr;
    QAction* import_ = nullptr;
    QList<QAction*> actions_;
    QList<QAction*> templateActions_;
    QList<QAction*> viewportActions_;
    QAction* undo_ = nullptr;
    QAction* redo_ = nullptr;
    QAction* delete_ = nullptr;
    QAction* duplicate_ = nullptr;
    Preferences preferences_;
    QMap<QString, QList<QKeySequence>> defaultShortcuts_;
};

} // namespace glint::editor
