// The FrameRenderer (epoxy GL) comes before any Qt OpenGL header in this translation unit.
#include "renderer/frame_renderer.h"
#include "renderer/gpu_scene/texture_arrays.h"
#include "renderer/raster/gpu_sync.h"
#include "renderer/raster/preview_pass.h"

#include "editor/viewport/render_host.h"

#include "editor/document/document.h"
#include "editor/viewport/debug_image.h"
#include "editor/viewport/scene_picker.h"
#include "editor/viewport/scene_preparer.h"
#include "editor/viewport/view_picking.h"
#include "scene/anim/scene_at_time.h"
#include "scene/core/light_sources.h"

#include <QElapsedTimer>
#include <QTimer>

#include <cmath>

namespace glint::editor {

namespace {

// Resolved by the document: an absolute path chosen in an untitled scene is read as it is.
std::filesystem::path environmentPath(const Document& document) { return document.environmentPath(); }

// Changes after which the scene may have gained or lost its last light source (sceneLighting):
// not transform drags, names, the timeline or the display.
bool mayChangeLighting(const ChangeSet& changes) {
    for (const Change c : {Change::Structure, Change::Visibility, Change::Light, Change::Geometry, Change::Material,
                           Change::Environment, Change::Assets})
        if (changes.has(c)) return true;
    return false;
}

// Real-time frames while the view moves (the BVH heat map counts: a plain mean, never reconstructed).
bool realTime(const ViewRequest& request) { return request.moving && request.mode != ViewMode::BvhCost; }

double elapsedMs(const QElapsedTimer& clock) { return double(clock.nsecsElapsed()) / 1e6; }

// The still view's bands and filter steps as the budget sizes them now (none while moving).
void sliceByBudget(renderer::FrameSettings& s, const FrameBudget& budget, bool moving) {
    s.rowsPerFrame = moving ? 0 : budget.rowsPerFrame(s.height);
    s.denoiseRowsPerFrame = moving ? 0 : budget.denoiseRowsPerFrame(s.height);
}

// The diagonal of what the picker knows of, else `otherwise`.
double sceneSize(const ScenePicker& picker, double otherwise) {
    bvh::Aabb bounds;
    for (const bvh::Aabb& box : picker.instanceBounds()) bounds.grow(box);
    return bounds.empty() ? otherwise : std::max(1e-6, double(glm::length(bounds.extent())));
}

// Depth planes that hold everything the picker knows of (an engine modelled in millimetres is
// hundreds of units across: a fixed far plane cut it away).
glm::dvec2 sceneDepthRange(const ViewCamera& camera, const ScenePicker& picker) {
    bvh::Aabb bounds;
    for (const bvh::Aabb& box : picker.instanceBounds()) bounds.grow(box);
    return depthRange(camera, bounds);
}

} // namespace

renderer::CameraSetup cameraSetupOf(const ViewCamera& camera, int width, int height) {
    renderer::CameraSetup setup;
    setup.worldFromCamera = camera.worldFromCamera();
    const float t = std::tan(0.5f * camera.yfov);
    setup.halfExtent = {t * float(width) / float(std::max(1, height)), t};
    setup.focusDistance = static_cast<float>(camera.distance);
    return setup;
}

RenderHost::RenderHost(Document& document, QObject* parent)
    : QObject(parent), document_(document), preparer_(std::make_unique<ScenePreparer>()),
      picking_(std::make_unique<ViewPicking>()) {
    connect(preparer_.get(), &ScenePreparer::progress, this, &RenderHost::showPreparationProgress);
    connect(preparer_.get(), &ScenePreparer::finished, this, &RenderHost::paintRequested);
    connect(preparer_.get(), &ScenePreparer::failed, this, [this](const QString& message) {
        stats_.error = message;
        stats_.preparing = false;
        emit paintRequested();
    });
    connect(&document_, &Document::changed, this, &RenderHost::onDocumentChanged);
    connect(&document_, &Document::fileChanged, this, &RenderHost::onFileChanged);
    connect(&document_, &Document::timeChanged, this, [this] {
        timeDirty_ = true;
        picking_->noteTime();
        emit paintRequested();
    });
    connect(picking_.get(), &ViewPicking::arrived, this, &RenderHost::paintRequested);
    noteLighting();
}

RenderHost::~RenderHost() {
    preparer_.reset(); // cancels and waits for the worker's current step
    renderer_.reset();
    preview_.reset();
}

void RenderHost::onDocumentChanged(const ChangeSet& changes) {
    if (preview_ && (changes.has(Change::Geometry) || changes.has(Change::Structure))) previewStale_ = true;
    // A change the GPU scene cannot take in place supersedes the preparation in flight, and the
    // image shown until the next upload is no longer the document's.
    if (!renderer::FrameRenderer::mayApplyInPlace(changes)) {
        if (preparer_->busy()) fullUpload_ = true;
        stats_.samples = 0;
    }
    pending_.merge(changes);
    if (mayChangeLighting(changes)) noteLighting();
    picking_->noteChange(changes);
    emit paintRequested();
}

void RenderHost::onFileChanged() {
    preparer_->cancel(); // another document: the old preparation is of no use
    stats_.samples = 0;
    fullUpload_ = true;
    showPrevious_ = false;
    reportedWarnings_.clear(); // warnings are de-duplicated per opened file
    picking_->noteNewFile();
    emit paintRequested();
}

void RenderHost::initializeGl() {
    renderer_ = std::make_unique<renderer::FrameRenderer>();
    preview_ = std::make_unique<renderer::raster::PreviewPass>();
    textureLimits_ = renderer::queryTextureLimits();
    ++stats_.contexts;
    gpuCurrent_ = false;
    fullUpload_ = !preparer_->busy() && !preparer_->hasResult(); // a finished result is uploaded as it is
    timeDirty_ = true;
}

void RenderHost::releaseGl() {
    renderer_.reset();
    preview_.reset();
    // The new context needs a GPU scene: the preparation in flight will do (its data is CPU-side),
    // else a new one starts at the next paint.
    gpuCurrent_ = false;
    showPrevious_ = false;
    fullUpload_ = !preparer_->busy() && !preparer_->hasResult();
}

// Starts the CPU stage of a new GPU scene on the worker; pending changes are part of it.
void RenderHost::startPreparation() {
    stats_.error.clear();
    stats_.preparing = true;
    stats_.preparation = tr("Preparing the scene");
    ++stats_.preparations;
    preparer_->start(document_.scene(), document_.currentTime(), environmentPath(document_), textureLimits_);
    picking_->preparationStarted();
    fullUpload_ = false;
    gpuCurrent_ = false;
    pending_ = {};
}

// The GL stage, on the GL thread: a prepared scene becomes the renderer's.
void RenderHost::uploadPrepared(PreparedDocument prepared) {
    QElapsedTimer upload;
    upload.start();
    stats_.preparing = false;
    showPrevious_ = false; // until the upload succeeds
    picking_->adoptPrepared(std::move(prepared.picker));
    renderer_->setPreparedScene(std::move(prepared.document), prepared.time, std::move(prepared.gpu));
    renderer::raster::finishGpuWork();
    stats_.uploadMs = elapsedMs(upload);
    stats_.prepareMs = prepared.milliseconds;
    ++stats_.uploads;
    gpuCurrent_ = true;
    showPrevious_ = true;
    timeDirty_ = true;
    reportRendererWarnings();
}

// Brings the GPU scene up to the document where that is cheap, starts a preparation where it is
// not; false while the renderer has no current scene to draw.
bool RenderHost::syncGpuScene() {
    if (std::unique_ptr<PreparedDocument> ready = preparer_->take()) uploadPrepared(std::move(*ready));
    // After a failed preparation, the next change tries again.
    if (fullUpload_ || (!gpuCurrent_ && !preparer_->busy() && pending_.flags != 0)) startPreparation();
    if (preparer_->busy() || !gpuCurrent_) return false;
    if (pending_.flags != 0) {
        QElapsedTimer clock;
        clock.start();
        const bool inPlace = renderer_->applyChangesInPlace(document_.scene(), pending_);
        renderer::raster::finishGpuWork();
        stats_.inPlaceMs = elapsedMs(clock);
        if (!inPlace) {
            startPreparation();
            return false;
        }
        pending_ = {};
    }
    if (timeDirty_) {
        renderer_->setTime(document_.currentTime());
        timeDirty_ = false;
    }
    return true;
}

void RenderHost::paint(const ViewRequest& request, unsigned int framebuffer) {
    if (!renderer_) return;
    lastRaster_ = showsRaster(request.mode);
    lastMoving_ = realTime(request);
    try {
        if (lastRaster_) paintPreview(request, framebuffer);
        else if (!syncGpuScene()) paintWhilePreparing(request, framebuffer);
        else paintTraced(request, framebuffer);
    } catch (const std::exception& e) {
        stats_.error = QString::fromStdString(e.what());
    }
    finishPaint();
}

// Ends every paint: figures out, and the next paint scheduled while work remains. The next slice
// is a queued update, not a loop, so the event loop answers in between.
void RenderHost::finishPaint() {
    ++stats_.paints;
    stats_.moving = lastMoving_;
    stats_.sampleCap = sampleCap_;
    emit statsChanged();
    if (workRemains()) QTimer::singleShot(0, this, &RenderHost::paintRequested);
}

// The scheduling invariant (render_host.h): false only when nothing on screen can change without
// a new input: an error is shown, a raster view is drawn, a preparation will announce itself, or
// the traced image is current, whole, at full resolution and capped or paused.
bool RenderHost::workRemains() const {
    if (!renderer_ || !stats_.error.isEmpty() || lastRaster_) return false;
    if (preparer_->hasResult() || fullUpload_) return true;
    if (preparer_->busy()) return false; // its finished() asks for the paint that uploads it
    if (pending_.flags != 0 || timeDirty_) return true;
    return wantsSamples();
}

// Whether the renderer has more to do for the current picture.
bool RenderHost::wantsSamples() const {
    if (renderer_->imageStage() != renderer::ImageStage::Complete) return true; // not current, or not whole
    if (renderer_->denoisePending()) return true; // the image shown waits for the filter of the mean
    if (lastMoving_) return true; // real-time frames keep refining their history until the view settles
    if (paused_ || renderer_->converged()) return false; // converged: adaptive sampling stopped every pixel
    return sampleCap_ <= 0 || renderer_->sampleCount() < sampleCap_;
}

// Meanwhile: the last image while it is of this document, else the raster preview.
void RenderHost::paintWhilePreparing(const ViewRequest& request, unsigned int framebuffer) {
    stats_.samples = 0; // none of the document as it is now
    stats_.stage = ViewStage::Preparing;
    stats_.filtering = false;
    readBack_ = QImage();
    // A scene uploaded but not yet rendered has no image to show: the preview stands in.
    if (showPrevious_ && renderer_->hasScene() && renderer_->drawTo(framebuffer, request.width, request.height)) {
        renderer_->drawOutline(framebuffer, request.width, request.height, outlinedNodes());
        return;
    }
    paintPreview(request, framebuffer);
}

void RenderHost::paintPreview(const ViewRequest& request, unsigned int framebuffer) {
    if (previewStale_) {
        preview_->invalidate();
        previewStale_ = false;
    }
    readBack_ = QImage();
    renderer::raster::PreviewView v;
    v.width = request.width;
    v.height = request.height;
    v.clipFromWorld = clipFromWorld(*request.camera, request.aspect, sceneDepthRange(*request.camera, picker(request.mode)));
    v.eye = glm::vec3(request.camera->position());
    v.style = request.mode == ViewMode::Wireframe ? renderer::raster::PreviewStyle::Wireframe : renderer::raster::PreviewStyle::Solid;
    v.highlight = document_.currentNode();
    const Scene& scene = document_.scene();
    if (scene.animations.empty()) preview_->draw(scene, framebuffer, v);
    else preview_->draw(sceneAt(scene, document_.currentTime()), framebuffer, v);
}

void RenderHost::paintTraced(const ViewRequest& request, unsigned int framebuffer) {
    configure(request);
    if (stats_.error.isEmpty() && wantsSamples()) renderSlice(lastMoving_);
    renderer_->drawTo(framebuffer, request.width, request.height);
    renderer_->drawOutline(framebuffer, request.width, request.height, outlinedNodes());
    readBack_ = showsReadBack(request.mode) ? debugImage(renderer_->readImages(), request.mode) : QImage();
    noteStage(request);
}

// The selected nodes and what they hold: selecting a group outlines its objects.
std::vector<NodeId> RenderHost::outlinedNodes() const {
    const Scene& scene = document_.scene();
    std::vector<NodeId> nodes;
    for (const NodeId selected : document_.selection())
        if (scene.contains(selected)) {
            const std::vector<NodeId> subtree = scene.subtree(selected);
            nodes.insert(nodes.end(), subtree.begin(), subtree.end());
        }
    return nodes;
}

void RenderHost::configure(const ViewRequest& request) {
    const RenderSettings& project = document_.scene().settings.render;
    renderer::FrameSettings s = renderer_->settings();
    const bool moving = realTime(request);
    s.configuration = moving ? renderer::Configuration::Full : renderer::Configuration::Accumulate;
    s.spp = 1;
    s.maxSamples = sampleCap_; // raising it continues the mean
    s.denoise = denoise_ && request.mode == ViewMode::PathTraced;
    s.bounces = project.bounces;
    s.seed = project.seed;
    s.exposure = project.exposure;
    s.clamp = project.clamp;
    s.sampleBlock = project.sampleBlock;
    s.adaptive = project.adaptive; // Accumulate only: the renderer leaves the moving view alone
    s.bloom = {project.bloom.strength, project.bloom.radius};
    s.view = request.mode == ViewMode::AmbientOcclusion ? renderer::DebugView::AmbientOcclusion
             : request.mode == ViewMode::BvhCost        ? renderer::DebugView::BvhCost
                                                        : renderer::DebugView::None;
    // Occlusion within a tenth of the scene's size: the AO view of a model in millimetres was white.
    if (request.mode == ViewMode::AmbientOcclusion) s.aoDistance = float(0.1 * sceneSize(picker(request.mode), 10.0));
    s.region = request.region;
    const int divisor = moving ? budget_.movingDivisor() : 1;
    stats_.divisor = divisor; // of this paint's frames (the budget may pick another for the next)
    s.width = std::max(1, request.width / divisor);
    s.height = std::max(1, request.height / divisor);
    sliceByBudget(s, budget_, moving);
    s.previewDivisor = moving ? 1 : budget_.previewDivisor(s.height, s.denoise ? renderer::denoiseRowsPerFiltering(s.height) : 0);
    if (!(s == renderer_->settings())) renderer_->setSettings(s);
    if (request.lookThrough.valid() && document_.scene().contains(request.lookThrough))
        renderer_->useSceneCamera(document_.scene().at(request.lookThrough).name);
    else
        renderer_->setCamera(cameraSetupOf(*request.camera, s.width, s.height));
}

// Frames until this paint's budget is spent (one while moving: the next input comes first). Each
// frame's time teaches the budget what the next one may hold.
void RenderHost::renderSlice(bool moving) {
    QElapsedTimer paint;
    paint.start();
    stats_.framesThisPaint = 0;
    double last = 0.0;
    do {
        if (!moving) { // bands and filter steps follow what the last one taught
            renderer::FrameSettings s = renderer_->settings();
            sliceByBudget(s, budget_, false);
            if (!(s == renderer_->settings())) renderer_->setSettings(s);
        }
        QElapsedTimer frame;
        frame.start();
        renderer_->renderFrame();
        renderer::raster::finishGpuWork();
        last = elapsedMs(frame);
        const renderer::FrameWork work = renderer_->lastFrameWork();
        const renderer::FrameSettings& s = renderer_->settings();
        if (moving) budget_.reportMoving(last, budget_.movingDivisor()); // the divisor configure() used
        else if (work.denoiseRows > 0) budget_.reportDenoiseRows(last, work.denoiseRows);
        else if (work.previewRows > 0) budget_.reportPreview(last, work.previewRows, s.previewDivisor);
        else if (work.rows > 0) budget_.reportRows(last, work.rows);
        ++stats_.framesThisPaint;
    } while (!moving && wantsSamples() &&
             budget_.anotherFits(elapsedMs(paint), last, budget_.plannedMs(renderer_->settings().height, renderer_->denoisePending())));
    stats_.frameMs = last;
    stats_.paintMs = elapsedMs(paint);
}

void RenderHost::noteStage(const ViewRequest& request) {
    const renderer::ImageStage image = renderer_->imageStage();
    stats_.samples = renderer_->sampleCount();
    stats_.refinePercent = 0;
    stats_.filtering = renderer_->denoisePending();
    const std::optional<double> converged = lastMoving_ ? std::nullopt : renderer_->convergedShare();
    stats_.convergedPercent = converged ? int(*converged * 100.0) : -1; // floored: 100 only when every pixel stopped
    if (lastMoving_) {
        stats_.stage = ViewStage::Coarse;
    } else if (image == renderer::ImageStage::Preview || image == renderer::ImageStage::None) {
        stats_.stage = ViewStage::Coarse;
        stats_.divisor = renderer_->settings().previewDivisor;
    } else if (image == renderer::ImageStage::Refining && stats_.samples == 0) {
        stats_.stage = ViewStage::Refining;
        stats_.refinePercent = 100 * renderer_->rowsTraced() / std::max(1, renderer_->rowsToTrace());
        if (renderer_->previewShown()) stats_.divisor = renderer_->settings().previewDivisor;
    } else if (stats_.filtering) {
        stats_.stage = ViewStage::Accumulating; // not converged until the filtering at the cap is shown
    } else if (renderer_->converged()) {
        stats_.stage = ViewStage::NoiseConverged;
    } else if (sampleCap_ > 0 && stats_.samples >= sampleCap_) {
        stats_.stage = ViewStage::Converged;
    } else {
        stats_.stage = paused_ ? ViewStage::Paused : ViewStage::Accumulating;
    }
    (void)request;
}

void RenderHost::showPreparationProgress(renderer::PreparationStage stage, int done, int total) {
    QString what;
    switch (stage) {
    case renderer::PreparationStage::Meshes: what = tr("building mesh BVHs"); break;
    case renderer::PreparationStage::Textures: what = tr("decoding textures"); break;
    case renderer::PreparationStage::Environment: what = tr("loading the environment"); break;
    case renderer::PreparationStage::Packing: what = tr("packing the scene"); break;
    case renderer::PreparationStage::Picking: what = tr("building the click picker"); break;
    }
    stats_.preparation = total > 1 ? tr("Preparing the scene: %1 %2/%3").arg(what).arg(done + 1).arg(total)
                                   : tr("Preparing the scene: %1").arg(what);
    emit statsChanged();
}

// Renderer warnings reach the log panel through the document, as the loader's do, each once per
// opened file (every preparation of the same scene reports the same ones).
void RenderHost::reportRendererWarnings() {
    const QString file = document_.filePath().isEmpty() ? document_.displayName() : document_.filePath();
    for (const Warning& w : renderer_->warnings())
        if (reportedWarnings_.insert({w.code, w.message}).second)
            document_.reportWarning(QStringLiteral("%1: %2").arg(file, QString::fromStdString(w.message)));
}

// Most glTF assets carry no light and the default environment is black: say why the image is.
void RenderHost::noteLighting() {
    switch (sceneLighting(document_.scene())) {
    case SceneLighting::None:
        stats_.hint = tr("Nothing in the scene emits light, so the path-traced image is black: add a light (Add > Light > "
                         "Studio environment lights any model) or an emissive material, or give the environment a colour or "
                         "an image (Scene tab).");
        break;
    case SceneLighting::EmissiveTexturesOnly:
        stats_.hint = tr("Only emissive textures give light in this scene, so most of the path-traced image is dark: add a "
                         "light (Add > Light > Studio environment lights any model), or give the environment a colour or an "
                         "image (Scene tab).");
        break;
    case SceneLighting::Lit: stats_.hint.clear(); break;
    }
}

renderer::FrameImages RenderHost::readImages() { return renderer_ ? renderer_->readImages() : renderer::FrameImages{}; }

const ScenePicker& RenderHost::picker(ViewMode mode) {
    // The path-traced views get the picker with their GPU scene; the raster views prepare none.
    const bool preparationComing = preparer_->busy() || (!showsRaster(mode) && renderer_ && stats_.error.isEmpty());
    return picking_->picker(document_.scene(), document_.currentTime(), preparationComing);
}

void RenderHost::setPaused(bool paused) {
    paused_ = paused;
    emit paintRequested();
}

void RenderHost::setDenoise(bool on) {
    denoise_ = on;
    emit paintRequested();
}

void RenderHost::setSampleCap(int samples) {
    sampleCap_ = std::max(0, samples);
    emit paintRequested();
}

} // namespace glint::editor
