#pragma once
// The viewport's input tools as one explicit state machine: what a mouse press starts (orbit, pan,
// zoom, fly, a gizmo drag, a click that selects or inspects, a render-region drag, a focus pick),
// how moves, releases, keys and the wheel act in each state, and what ends each state. Navigation
// changes the view's camera, gizmo drags push commands (GizmoDrag), and clicks go back to the view
// as signals (select, inspect, focus). No GL and no drawing here: the overlay presenter draws what
// the tools show (the gizmo's active axis, the region being dragged).
#include "editor/viewport/gizmo_math.h"
#include "editor/viewport/region_tool.h"

#include <QObject>
#include <QPointF>
#include <QTimer>

#include <memory>
#include <optional>
#include <set>

class QKeyEvent;
class QMouseEvent;
class QWheelEvent;

namespace glint::editor {

class Document;
class GizmoDrag;
class RenderView;

enum class Tool {
    Idle,
    Orbit,       // left drag with Alt, or middle drag
    Pan,         // Shift + middle drag
    Zoom,        // Ctrl + middle drag (the wheel zooms in any state)
    Fly,         // right drag: mouse look, W/A/S/D/Q/E move
    Gizmo,       // left drag on a handle of the selected node's gizmo
    Click,       // left press elsewhere: a click selects (or inspects) unless it turns into a drag
    RegionArmed, // Ctrl+B: the next left drag draws the render region
    RegionDrag,
    FocusArmed,  // Ctrl+Shift+F: the next left click picks the focus distance
};

class ViewTools : public QObject {
    Q_OBJECT
public:
    ViewTools(RenderView& view, Document& document);
    ~ViewTools() override;

    Tool tool() const { return tool_; }
    bool navigating() const; // the camera or a node is being dragged right now

    GizmoMode gizmoMode() const { return gizmoMode_; }
    void setGizmoMode(GizmoMode mode);
    GizmoSpace gizmoSpace() const { return gizmoSpace_; }
    void setGizmoSpace(GizmoSpace space);
    GizmoSnap& snap() { return snap_; }
    int activeGizmoAxis() const; // -1: none

    const RegionTool& region() const { return region_; }
    void armRenderRegion();
    void setRenderRegion(const std::optional<QRectF>& fractions);
    void armFocusPick(bool on);
    void setInspecting(bool on) { inspecting_ = on; }

    // Each takes the event when it returns true (the view passes the rest on to QWidget).
    void press(QMouseEvent* event);
    void move(QMouseEvent* event);
    void release(QMouseEvent* event);
    void wheel(QWheelEvent* event);
    bool keyPress(QKeyEvent* event);
    void keyRelease(QKeyEvent* event);
    void focusOut();

signals:
    void clicked(QPointF at, bool extend); // a click without a drag: select (Shift extends)
    void inspected(QPointF at);            // the same with the pixel inspector on
    void focusClicked(QPointF at);
    void gizmoModeChanged(GizmoMode mode);
    void gizmoSpaceChanged(GizmoSpace space);

private:
    void enter(Tool tool);
    bool startGizmoDrag(QPointF at);
    void flyStep();
    void finishCameraMove(const glm::dvec3& eyeBefore);

    RenderView& view_;
    Document& document_;
    Tool tool_ = Tool::Idle;
    GizmoMode gizmoMode_ = GizmoMode::Translate;
    GizmoSpace gizmoSpace_ = GizmoSpace::World;
    GizmoSnap snap_;
    std::unique_ptr<GizmoDrag> gizmoDrag_;
    RegionTool region_;
    bool inspecting_ = false;
    QPointF lastMouse_;
    QPointF pressMouse_;
    QTimer flyTimer_;
    std::set<int> flyKeys_;
};

} // namespace glint::editor
