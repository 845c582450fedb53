#pragma once
// The viewport's GL surface, kept thin: it holds the view's own camera, mode and the scene camera
// it may look through, and hands the work to three parts with one job each:
// - RenderHost (render_host.h): the GPU scene, what each paint renders, and the invariant that a
//   paint is scheduled until the image on screen is the current one, whole, at full resolution;
// - ViewTools (view_tools.h): mouse and keys as one state machine (navigation, gizmo drags,
//   clicks, render region, focus pick);
// - OverlayPresenter (overlay_presenter.h): what is drawn over the image.
// When Qt re-creates the context (re-docking or floating the viewport), the host uploads the GPU
// scene again from a preparation (the one in flight, if any).
#include "editor/document/node_placement.h"
#include "editor/viewport/gizmo_math.h"
#include "editor/viewport/overlay_presenter.h"
#include "editor/viewport/render_host.h"
#include "editor/viewport/view_camera.h"
#include "editor/viewport/view_modes.h"
#include "editor/viewport/view_tools.h"

#include <QElapsedTimer>
#include <QOpenGLWidget>
#include <QPoint>
#include <QTimer>

#include <optional>

namespace glint::editor {

class Document;
class ScenePicker;
class ViewPicking;

class RenderView : public QOpenGLWidget {
    Q_OBJECT
public:
    RenderView(Document& document, QWidget* parent = nullptr);
    ~RenderView() override;

    ViewCamera& camera() { return camera_; }
    void setCamera(const ViewCamera& camera);
    ViewMode mode() const { return mode_; }
    void setMode(ViewMode mode);
    GizmoMode gizmoMode() const { return tools_.gizmoMode(); }
    void setGizmoMode(GizmoMode mode) { tools_.setGizmoMode(mode); }
    GizmoSpace gizmoSpace() const { return tools_.gizmoSpace(); }
    void setGizmoSpace(GizmoSpace space) { tools_.setGizmoSpace(space); }
    GizmoSnap& snap() { return tools_.snap(); }
    const ViewTools& tools() const { return tools_; }
    void setLookThrough(NodeId camera); // none: the viewport's own camera
    NodeId lookThrough() const { return lookThrough_; }
    void setPaused(bool paused) { host_.setPaused(paused); } // no samples beyond a current, whole image
    bool paused() const { return host_.paused(); }
    void setSampleCap(int samples) { host_.setSampleCap(samples); } // 0: none
    int sampleCap() const { return host_.sampleCap(); }
    void setFrameBudget(double ms) { host_.budget().setBudgetMs(ms); }
    void setDenoise(bool on) { host_.setDenoise(on); } // the still image filtered, or the raw mean
    bool denoise() const { return host_.denoise(); }
    void setInspecting(bool on) { tools_.setInspecting(on); }
    void takeSnapshot();                // A/B: the current image becomes A
    void setComparing(bool on);         // A on the left of a divider, the live view on the right
    bool hasSnapshot() const { return overlays_.hasSnapshot(); }
    // Render region (region_tool.h): arm a drag, or set it as fractions of the view (nullopt clears).
    void armRenderRegion() { tools_.armRenderRegion(); }
    void setRenderRegion(const std::optional<QRectF>& fractions) { tools_.setRenderRegion(fractions); }
    const std::optional<QRectF>& renderRegion() const { return tools_.region().region(); }
    const ViewportStats& stats() const { return host_.stats(); }
    // Pick focus (focus_pick.h): the next left click goes to focusClicked instead of selecting.
    void armFocusPick(bool on) { tools_.armFocusPick(on); }
    bool focusPickArmed() const { return tools_.tool() == Tool::FocusArmed; }

    void frameSelection();
    // The node under a widget position (no selection change): a light's or camera's icon within
    // kIconPickRadius, else the nearest surface (none while the picker is on its way).
    NodeId pickAt(QPointF widgetPos);
    void selectAt(QPointF widgetPos, bool extend);
    void inspectPixel(QPointF widgetPos);
    const ScenePicker& picker();        // empty (picks nothing) until the document's arrives
    ViewPicking& picking() { return host_.picking(); }
    GizmoFrame gizmoFrame(NodeId node) const;
    std::optional<QPointF> project(const glm::dvec3& world) const; // world -> widget coordinates
    bvh::Ray rayAt(QPointF widgetPos) const;
    // The camera moved (cameraMoved() is emitted), or something is dragged: the view counts as
    // moving until it settles.
    void noteMotion(bool cameraMoved);
    // Where new nodes land (node_placement.h): the orbit centre, the size of the scene in view,
    // the free space above the centre.
    ViewFocus focus();

signals:
    void statsChanged();
    void pixelInspected(QPoint pixel, float r, float g, float b, float a);
    void cameraMoved();
    void focusClicked(QPointF widgetPos);

protected:
    void initializeGL() override;
    void resizeGL(int w, int h) override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void keyReleaseEvent(QKeyEvent* event) override;
    void focusOutEvent(QFocusEvent* event) override;
    void changeEvent(QEvent* event) override; // a language change: the hint and status texts follow

private:
    void releaseGl();
    void followLookThrough();
    void placeAtCamera(NodeId camera);
    bool moving() const;

    Document& document_;
    RenderHost host_;
    ViewTools tools_;
    OverlayPresenter overlays_;
    ViewCamera camera_;
    ViewMode mode_ = ViewMode::PathTraced;
    NodeId lookThrough_{};
    QElapsedTimer sinceMotion_;
    QTimer settleTimer_; // one paint after motion stops: switch to the still configuration
};

} // namespace glint::editor
