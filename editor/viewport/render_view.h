#pragma once
// The viewport's GL surface: hosts a renderer::FrameRenderer in the QOpenGLWidget's context and
// time-slices it (each paint renders as many frames as fit its budget, then yields to the event
// loop), draws the overlays, and turns mouse and keys into navigation, picks and gizmo drags.
// The GPU scene is prepared on a worker thread (ScenePreparer: BVHs, textures, packing) and
// uploaded here; meanwhile the view shows its last image of the document, or the raster preview.
// Transform, light and material-value edits are applied in place at once (a top-level rebuild).
// The click picker comes from worker threads too (ViewPicking); lights and cameras are clicked on
// their icons.
// When Qt re-creates the context (re-docking or floating the viewport), the GPU scene is uploaded
// again from a preparation (the one in flight, if any).
#include "editor/viewport/frame_budget.h"
#include "editor/viewport/gizmo_math.h"
#include "editor/viewport/region_tool.h"
#include "editor/viewport/view_camera.h"
#include "editor/viewport/view_modes.h"
#include "renderer/gpu_scene/texture_set.h"
#include "scene/history/change_set.h"

#include <QElapsedTimer>
#include <QImage>
#include <QOpenGLWidget>
#include <QPoint>
#include <QTimer>

#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>

namespace glint::renderer {
class FrameRenderer;
namespace raster {
class PreviewPass;
}
} // namespace glint::renderer

namespace glint::editor {

class Document;
class ScenePicker;
class ViewPicking;
class GizmoDrag;
class ScenePreparer;
struct PreparedDocument;

// Figures of the last paint, for the status bar and the tests.
struct ViewportStats {
    int samples = 0;        // in the running mean behind the shown image (0 while the scene is prepared)
    int framesThisPaint = 0;
    double paintMs = 0.0;   // GL work of the last paint (frames finished on the GPU)
    double frameMs = 0.0;   // the last frame alone
    int divisor = 1;        // resolution divisor of the last frame
    long long paints = 0;
    int contexts = 0;       // GL contexts this view has built its GPU scene in (re-docking makes new ones)
    QString error;          // why nothing is drawn (scene too big for the GPU, ...), or empty
    QString hint;           // why the image is black although it is drawn (nothing emits light), or empty
    // GPU scene preparation (on a worker thread): in progress, and a line for the status bar.
    bool preparing = false;
    QString preparation;
    int preparations = 0;   // preparations started (a newer one cancels the one in flight)
    int uploads = 0;        // prepared scenes uploaded on the GL thread
    double prepareMs = 0.0; // the last upload's preparation on the worker
    double uploadMs = 0.0;  // and its upload on the GL thread
    double inPlaceMs = 0.0; // the last edit applied in place (transforms, lights, material values)
};

class RenderView : public QOpenGLWidget {
    Q_OBJECT
public:
    RenderView(Document& document, QWidget* parent = nullptr);
    ~RenderView() override;

    ViewCamera& camera() { return camera_; }
    void setCamera(const ViewCamera& camera);
    ViewMode mode() const { return mode_; }
    void setMode(ViewMode mode);
    GizmoMode gizmoMode() const { return gizmoMode_; }
    void setGizmoMode(GizmoMode mode);
    GizmoSnap& snap() { return snap_; }
    void setLookThrough(NodeId camera); // none: the viewport's own camera
    NodeId lookThrough() const { return lookThrough_; }
    void setPaused(bool paused);        // exports pause the viewport: it stops adding samples
    bool paused() const { return paused_; }
    void setInspecting(bool on) { inspecting_ = on; }
    void takeSnapshot();                // A/B: the current image becomes A
    void setComparing(bool on);         // A on the left of a divider, the live view on the right
    bool hasSnapshot() const { return !snapshot_.isNull(); }
    // Render region (region_tool.h): arm a drag, or set it as fractions of the view (nullopt clears).
    void armRenderRegion();
    void setRenderRegion(const std::optional<QRectF>& fractions);
    const std::optional<QRectF>& renderRegion() const { return region_.region(); }
    const ViewportStats& stats() const { return stats_; }
    // Pick focus (focus_pick.h): the next left click goes to focusClicked instead of selecting.
    void armFocusPick(bool on);
    bool focusPickArmed() const { return focusPickArmed_; }

    void frameSelection();
    // The node under a widget position (no selection change): a light's or camera's icon within
    // kIconPickRadius, else the nearest surface (none while the picker is on its way).
    NodeId pickAt(QPointF widgetPos);
    const ScenePicker& picker();        // empty (picks nothing) until the document's arrives
    ViewPicking& picking() { return *picking_; }
    GizmoFrame gizmoFrame(NodeId node) const;
    std::optional<QPointF> project(const glm::dvec3& world) const; // world -> widget coordinates
    bvh::Ray rayAt(QPointF widgetPos) const;

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

private:
    void releaseGl();
    void followLookThrough();
    void placeAtCamera(NodeId camera);
    bool syncGpuScene();
    void noteLighting();
    void startPreparation();
    void uploadPrepared(PreparedDocument prepared);
    void paintWhilePreparing();
    void showPreparationProgress(const QString& stage, int done, int total);
    void reportRendererWarnings();
    void configure(bool moving, int divisor);
    void renderSlice(bool moving, int divisor);
    void drawOverlays();
    void paintPreview();
    void inspectPixel(QPointF widgetPos);
    void noteMotion();
    bool moving() const;
    bool converged() const;
    void scheduleNextPaint();
    void flyStep();
    void selectAt(QPointF widgetPos, bool extend);

    Document& document_;
    std::unique_ptr<renderer::FrameRenderer> renderer_;
    std::unique_ptr<ScenePreparer> preparer_; // CPU stage of the GPU scene, on a worker thread
    renderer::TextureLimits textureLimits_;   // of the GL context, read on the GL thread
    bool gpuCurrent_ = false;   // the renderer's GPU scene is the document's (bar pending_ changes)
    bool showPrevious_ = false; // while preparing, the last image is of this document: keep showing it
    std::set<std::pair<std::string, std::string>> reportedWarnings_; // (code, message) since the file was opened
    std::unique_ptr<renderer::raster::PreviewPass> preview_;
    bool previewStale_ = false;
    std::unique_ptr<ViewPicking> picking_; // the click picker, built on worker threads
    std::unique_ptr<GizmoDrag> gizmoDrag_;
    ViewCamera camera_;
    ViewMode mode_ = ViewMode::PathTraced;
    GizmoMode gizmoMode_ = GizmoMode::Translate;
    GizmoSnap snap_;
    NodeId lookThrough_{};
    FrameBudget budget_;
    ViewportStats stats_;
    ChangeSet pending_;
    bool fullUpload_ = true;
    bool timeDirty_ = true;
    bool paused_ = false;
    bool inspecting_ = false;
    bool focusPickArmed_ = false;
    bool comparing_ = false;
    int stillDivisor_ = 0; // locked while the view is still, so accumulation is not reset
    QImage snapshot_;
    RegionTool region_;
    QImage readBack_;      // the G-buffer views' image
    QElapsedTimer sinceMotion_;
    QTimer settleTimer_;   // one paint after motion stops: switch to the still configuration
    QTimer flyTimer_;
    std::set<int> flyKeys_;
    enum class Drag { None, Orbit, Pan, Zoom, Fly, Gizmo, Click } drag_ = Drag::None;
    QPointF lastMouse_;
    QPointF pressMouse_;
};

} // namespace glint::editor
