#pragma once
// The editor's viewport panel: the path-traced (or preview) view of the document with its
// navigation, picking and gizmos, plus the actions the main window puts into its menus and
// toolbar (view modes on the number keys, frame selection on F, gizmo modes, snapping, look
// through a camera, make a scene camera from the view, pixel inspector, A/B snapshot).
#include "editor/viewport/view_modes.h"
#include "scene/core/ids.h"

#include <QList>
#include <QWidget>

class QAction;
class QActionGroup;

namespace glint::editor {

class Document;
class RenderView;

class Viewport : public QWidget {
    Q_OBJECT
public:
    Viewport(Document& document, QWidget* parent = nullptr);

    RenderView& view() { return *view_; }
    // One checkable action per view mode, shortcuts 1..9, in a group.
    QList<QAction*> viewModeActions() const;
    QAction* frameSelectionAction() const { return frameSelection_; }
    QAction* makeSceneCameraAction() const { return makeSceneCamera_; }
    QAction* lookThroughAction() const { return lookThrough_; }
    QAction* snapAction() const { return snap_; }
    // L: the move and rotate handles follow the selected node's own axes (off: the world's).
    QAction* localAxesAction() const { return localAxes_; }
    QAction* inspectAction() const { return inspect_; }
    QAction* snapshotAction() const { return snapshot_; }
    QAction* compareAction() const { return compare_; }
    QAction* renderRegionAction() const { return renderRegion_; }      // Ctrl+B: drag a render region
    QAction* clearRenderRegionAction() const { return clearRenderRegion_; } // Ctrl+Alt+B
    // Ctrl+Shift+F, then a click: the looked-through camera focuses on the surface clicked.
    QAction* pickFocusAction() const { return pickFocus_; }
    // Stops adding samples once the image is current and whole (edits are still shown).
    QAction* pauseAction() const { return pause_; }
    // The still image filtered by the preview denoiser (on), or the raw running mean.
    QAction* denoiseAction() const { return denoise_; }
    QList<QAction*> gizmoActions() const;
    // Every action above, for a menu.
    QList<QAction*> allActions() const;

public slots:
    void setPaused(bool paused); // while an export renders (kept apart from the user's pause)
    void setSampleCap(int samples); // the viewport's own sample count (preferences; 0: none)
    // Adds a camera node placed like the view (one undoable step) and selects it.
    NodeId makeSceneCamera();
    // Looks through the selected camera, or back through the viewport's own one.
    void toggleLookThrough();

signals:
    void statusMessage(const QString& text);
    void hint(const QString& text); // a tool's explanation (also shown in the window's status bar)

private:
    void createActions();
    void createPickFocusAction();
    void showHint(const QString& text);
    QString statusText() const;

    Document& document_;
    RenderView* view_ = nullptr;
    QActionGroup* modes_ = nullptr;
    QActionGroup* gizmos_ = nullptr;
    QAction* frameSelection_ = nullptr;
    QAction* makeSceneCamera_ = nullptr;
    QAction* lookThrough_ = nullptr;
    QAction* snap_ = nullptr;
    QAction* localAxes_ = nullptr;
    QAction* inspect_ = nullptr;
    QAction* snapshot_ = nullptr;
    QAction* compare_ = nullptr;
    QAction* pickFocus_ = nullptr;
    QAction* renderRegion_ = nullptr;
    QAction* clearRenderRegion_ = nullptr;
    QAction* pause_ = nullptr;
    QAction* denoise_ = nullptr;
    bool exportRunning_ = false;
};

} // namespace glint::editor
