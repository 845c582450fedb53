#pragma once
// The viewport's render host: keeps the GPU scene in step with the document (edits applied in place
// at once, or a new scene prepared on a worker by ScenePreparer and uploaded here), decides what each
// paint renders within its budget (FrameBudget), and draws the image into the widget's framebuffer.
//
// It owns the viewport's scheduling invariant (docs/ARCHITECTURE.md, "The viewport's frames"):
// whenever the image on screen is not the current one (document, camera, size, view mode, settings)
// at full resolution with every sample it is allowed, another paint is scheduled; only the sample
// cap or the pause stops work, and only once the image is current and whole. One function decides
// it (workRemains); every paint ends by asking it.
//
// Moving views render the real-time Full configuration at a reduced resolution; still views render
// Accumulate at full resolution, traced in bands of rows where a whole frame does not fit the
// budget, with a low-resolution preview standing in until the first full sample is complete.
// All GL calls happen in paint(), initializeGl() and releaseGl(), with the widget's context current.
#include "editor/viewport/frame_budget.h"
#include "editor/viewport/view_camera.h"
#include "editor/viewport/view_modes.h"
#include "renderer/gpu_scene/camera_setup.h"
#include "renderer/gpu_scene/prepared_scene.h"
#include "renderer/gpu_scene/texture_set.h"
#include "renderer/render_region.h"
#include "scene/history/change_set.h"

#include <QImage>
#include <QObject>
#include <QString>

#include <memory>
#include <set>
#include <string>
#include <utility>

namespace glint::renderer {
class FrameRenderer;
struct FrameImages;
namespace raster {
class PreviewPass;
}
} // namespace glint::renderer

namespace glint::editor {

class Document;
class ScenePicker;
class ScenePreparer;
class ViewPicking;
struct PreparedDocument;

// What the image on screen is, for the status bar: coarse (the moving view or the still preview),
// refining (full-resolution samples traced in bands, the coarse image still shown), accumulating,
// or done (the sample cap reached, adaptive sampling stopped every pixel, or paused with a current
// image).
enum class ViewStage { Preparing, Coarse, Refining, Accumulating, Converged, NoiseConverged, Paused };

// Figures of the last paint, for the status bar and the tests.
struct ViewportStats {
    int samples = 0;        // in the running mean behind the shown image (0 while the scene is prepared)
    int sampleCap = 0;      // the viewport's cap (0: none)
    ViewStage stage = ViewStage::Coarse;
    bool moving = false;    // the last paint rendered a moving view (real-time frames)
    int refinePercent = 0;  // of the sample being traced in bands
    int convergedPercent = -1; // of the pixels adaptive sampling has stopped; -1: it is off
    bool filtering = false; // the shown image waits for the filtering of the latest samples (in steps)
    int framesThisPaint = 0;
    double paintMs = 0.0;   // GL work of the last paint (frames finished on the GPU)
    double frameMs = 0.0;   // the last frame alone
    int divisor = 1;        // resolution divisor of the shown image (the preview's while it stands in)
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

// The renderer's camera for the view's own camera in a width x height image.
renderer::CameraSetup cameraSetupOf(const ViewCamera& camera, int width, int height);

// What the view asks to see in one paint.
struct ViewRequest {
    ViewMode mode = ViewMode::PathTraced;
    const ViewCamera* camera = nullptr; // the viewport's own camera
    NodeId lookThrough;                 // a scene camera to render through instead, or none
    int width = 1;                      // device pixels
    int height = 1;
    double aspect = 1.0;                // of the widget
    bool moving = false;
    renderer::RenderRegion region;
};

class RenderHost : public QObject {
    Q_OBJECT
public:
    explicit RenderHost(Document& document, QObject* parent = nullptr);
    ~RenderHost() override; // the context must be current if GL objects exist (releaseGl first)

    void initializeGl(); // a new context is current
    void releaseGl();    // the context is about to go: GL objects die with it
    bool hasGl() const { return renderer_ != nullptr; }

    // Renders what fits this paint's budget and draws the image into `framebuffer`; schedules
    // the next paint (paintRequested) while workRemains().
    void paint(const ViewRequest& request, unsigned int framebuffer);
    bool workRemains() const;

    // The image behind the G-buffer views (normals, albedo, ...) after the last paint, else null.
    const QImage& readBack() const { return readBack_; }
    // The last frame's linear images (GL context current).
    renderer::FrameImages readImages();

    const ViewportStats& stats() const { return stats_; }
    // The click picker of the document; empty while it is built (mode: raster views prepare no GPU scene).
    const ScenePicker& picker(ViewMode mode);
    ViewPicking& picking() { return *picking_; }

    void setPaused(bool paused);
    bool paused() const { return paused_; }
    void setSampleCap(int samples); // 0: no cap
    int sampleCap() const { return sampleCap_; }
    // The still view's image filtered (renderer::FrameSettings::denoise), or the raw mean.
    void setDenoise(bool on);
    bool denoise() const { return denoise_; }
    FrameBudget& budget() { return budget_; }
    // Sets the hint of a scene that nothing lights (stats().hint) again, in the language of the moment.
    void noteLighting();

signals:
    void paintRequested(); // the view should paint again
    void statsChanged();

private:
    bool syncGpuScene();
    void startPreparation();
    void uploadPrepared(PreparedDocument prepared);
    void paintWhilePreparing(const ViewRequest& request, unsigned int framebuffer);
    void paintPreview(const ViewRequest& request, unsigned int framebuffer);
    void paintTraced(const ViewRequest& request, unsigned int framebuffer);
    std::vector<NodeId> outlinedNodes() const;
    void configure(const ViewRequest& request);
    void renderSlice(bool moving);
    bool wantsSamples() const;
    void noteStage(const ViewRequest& request);
    void finishPaint();
    void showPreparationProgress(renderer::PreparationStage stage, int done, int total);
    void reportRendererWarnings();
    void onDocumentChanged(const ChangeSet& changes);
    void onFileChanged();

    Document& document_;
    std::unique_ptr<renderer::FrameRenderer> renderer_;
    std::unique_ptr<ScenePreparer> preparer_; // CPU stage of the GPU scene, on a worker thread
    std::unique_ptr<ViewPicking> picking_;    // the click picker, built on worker threads
    std::unique_ptr<renderer::raster::PreviewPass> preview_;
    renderer::TextureLimits textureLimits_;   // of the GL context, read on the GL thread
    FrameBudget budget_;
    ViewportStats stats_;
    ChangeSet pending_;         // document changes not yet on the GPU
    bool fullUpload_ = true;    // the next paint starts a preparation
    bool gpuCurrent_ = false;   // the renderer's GPU scene is the document's (bar pending_ changes)
    bool showPrevious_ = false; // while preparing, the last image is of this document: keep showing it
    bool timeDirty_ = true;
    bool previewStale_ = false;
    bool paused_ = false;
    bool lastRaster_ = false;   // the last paint drew a raster view: nothing left to render
    bool lastMoving_ = false;
    int sampleCap_ = 0;
    bool denoise_ = true;
    QImage readBack_;
    std::set<std::pair<std::string, std::string>> reportedWarnings_; // (code, message) since the file was opened
};

} // namespace glint::editor
