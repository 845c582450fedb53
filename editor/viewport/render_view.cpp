// The FrameRenderer (epoxy GL) comes before any Qt OpenGL header in this translation unit.
#include "renderer/frame_renderer.h"
#include "renderer/gpu_scene/texture_arrays.h"
#include "renderer/raster/gpu_sync.h"
#include "renderer/raster/preview_pass.h"

#include "editor/viewport/render_view.h"

#include "editor/document/document.h"
#include "editor/viewport/debug_image.h"
#include "editor/viewport/gizmo_drag.h"
#include "editor/viewport/overlay_painter.h"
#include "editor/viewport/initial_view.h"
#include "editor/viewport/scene_preparer.h"
#include "editor/viewport/scene_picker.h"
#include "editor/viewport/view_picking.h"
#include "renderer/configuration.h"
#include "scene/anim/scene_at_time.h"
#include "scene/core/light_sources.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QPainter>
#include <QToolTip>
#include <QWheelEvent>

#include <cmath>

namespace glint::editor {

namespace {

constexpr int kSettleMs = 150;     // the view counts as moving this long after the last change
constexpr int kFlyIntervalMs = 16;
constexpr double kClickSlopPixels = 4.0;

renderer::CameraSetup setupFrom(const ViewCamera& camera, int width, int height) {
    renderer::CameraSetup setup;
    setup.worldFromCamera = camera.worldFromCamera();
    const float t = std::tan(0.5f * camera.yfov);
    setup.halfExtent = {t * float(width) / float(std::max(1, height)), t};
    setup.focusDistance = static_cast<float>(camera.distance);
    return setup;
}

std::filesystem::path environmentPath(const Document& document) {
    const std::string& file = document.scene().settings.environment.file;
    if (file.empty() || document.folder().empty()) return {};
    return document.folder() / file;
}

// Changes after which the scene may have gained or lost its last light source (hasLightSource):
// not transform drags, names, the timeline or the display.
bool mayChangeLighting(const ChangeSet& changes) {
    for (const Change c : {Change::Structure, Change::Visibility, Change::Light, Change::Geometry, Change::Material,
                           Change::Environment, Change::Assets})
        if (changes.has(c)) return true;
    return false;
}

} // namespace

RenderView::RenderView(Document& document, QWidget* parent)
    : QOpenGLWidget(parent), document_(document), preparer_(std::make_unique<ScenePreparer>()),
      picking_(std::make_unique<ViewPicking>()) {
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(true);
    setAccessibleName(tr("Viewport"));
    setMinimumSize(64, 64);
    settleTimer_.setSingleShot(true);
    connect(&settleTimer_, &QTimer::timeout, this, qOverload<>(&QWidget::update));
    flyTimer_.setInterval(kFlyIntervalMs);
    connect(&flyTimer_, &QTimer::timeout, this, &RenderView::flyStep);
    connect(preparer_.get(), &ScenePreparer::progress, this, &RenderView::showPreparationProgress);
    connect(preparer_.get(), &ScenePreparer::finished, this, qOverload<>(&QWidget::update));
    connect(preparer_.get(), &ScenePreparer::failed, this, [this](const QString& message) {
        stats_.error = message;
        stats_.preparing = false;
        update();
    });
    connect(&document_, &Document::changed, this, [this](const ChangeSet& changes) {
        if (preview_ && (changes.has(Change::Geometry) || changes.has(Change::Structure))) previewStale_ = true;
        // A change the GPU scene cannot take in place supersedes the preparation in flight, and
        // the image shown until the next upload is no longer the document's.
        if (!renderer::FrameRenderer::mayApplyInPlace(changes)) {
            if (preparer_->busy()) fullUpload_ = true;
            stats_.samples = 0;
        }
        pending_.merge(changes);
        if (mayChangeLighting(changes)) noteLighting();
        picking_->noteChange(changes);
        followLookThrough();
        update();
    });
    connect(&document_, &Document::fileChanged, this, [this] {
        preparer_->cancel(); // another document: the old preparation is of no use
        stats_.samples = 0;
        fullUpload_ = true;
        showPrevious_ = false;
        reportedWarnings_.clear(); // warnings are de-duplicated per opened file
        picking_->noteNewFile();
        update();
    });
    connect(&document_, &Document::sceneReplaced, this, [this] {
        lookThrough_ = {};
        setCamera(initialView(document_.scene(), double(width()) / std::max(1, height())));
    });
    connect(&document_, &Document::timeChanged, this, [this] {
        timeDirty_ = true;
        picking_->noteTime();
        followLookThrough();
        update();
    });
    connect(&document_, &Document::selectionChanged, this, qOverload<>(&QWidget::update));
    connect(picking_.get(), &ViewPicking::arrived, this, qOverload<>(&QWidget::update));
    sinceMotion_.start();
    noteLighting();
}

RenderView::~RenderView() {
    preparer_.reset(); // cancels and waits for the worker's current step
    if (renderer_ && context()) {
        makeCurrent();
        renderer_.reset();
        preview_.reset();
        doneCurrent();
    }
}

void RenderView::releaseGl() {
    // The context is about to go (re-docking, floating, closing): GL objects die with it.
    makeCurrent();
    renderer_.reset();
    preview_.reset();
    doneCurrent();
    // The new context needs a GPU scene: the preparation in flight will do (its data is CPU-side),
    // else a new one starts at the next paint.
    gpuCurrent_ = false;
    showPrevious_ = false;
    // no preparer: the view is being destroyed
    fullUpload_ = !preparer_ || (!preparer_->busy() && !preparer_->hasResult());
}

void RenderView::initializeGL() {
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &RenderView::releaseGl, Qt::UniqueConnection);
    renderer_ = std::make_unique<renderer::FrameRenderer>();
    preview_ = std::make_unique<renderer::raster::PreviewPass>();
    textureLimits_ = renderer::queryTextureLimits();
    ++stats_.contexts;
    gpuCurrent_ = false;
    fullUpload_ = !preparer_->busy() && !preparer_->hasResult(); // a finished result is uploaded as it is
    timeDirty_ = true;
}

void RenderView::resizeGL(int, int) { stillDivisor_ = 0; }

// Starts the CPU stage of a new GPU scene on the worker; pending changes are part of it.
void RenderView::startPreparation() {
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
void RenderView::uploadPrepared(PreparedDocument prepared) {
    QElapsedTimer upload;
    upload.start();
    stats_.preparing = false;
    showPrevious_ = false; // until the upload succeeds
    picking_->adoptPrepared(std::move(prepared.picker));
    renderer_->setPreparedScene(std::move(prepared.document), prepared.time, std::move(prepared.gpu));
    renderer::raster::finishGpuWork();
    stats_.uploadMs = double(upload.nsecsElapsed()) / 1e6;
    stats_.prepareMs = prepared.milliseconds;
    ++stats_.uploads;
    gpuCurrent_ = true;
    showPrevious_ = true;
    timeDirty_ = true;
    reportRendererWarnings();
}

// Brings the GPU scene up to the document where that is cheap, starts a preparation where it is
// not; false while the renderer has no current scene to draw.
bool RenderView::syncGpuScene() {
    if (std::unique_ptr<PreparedDocument> ready = preparer_->take()) uploadPrepared(std::move(*ready));
    // After a failed preparation, the next change tries again.
    if (fullUpload_ || (!gpuCurrent_ && !preparer_->busy() && pending_.flags != 0)) startPreparation();
    if (preparer_->busy() || !gpuCurrent_) return false;
    if (pending_.flags != 0) {
        QElapsedTimer clock;
        clock.start();
        const bool inPlace = renderer_->applyChangesInPlace(document_.scene(), pending_);
        renderer::raster::finishGpuWork();
        stats_.inPlaceMs = double(clock.nsecsElapsed()) / 1e6;
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

// Meanwhile: the last image while it is of this document, else the raster preview.
void RenderView::paintWhilePreparing() {
    stats_.samples = 0; // none of the document as it is now
    const qreal dpr = devicePixelRatioF();
    // A scene uploaded but not yet rendered has no image to show: the preview stands in.
    if (showPrevious_ && renderer_->hasScene() &&
        renderer_->drawTo(defaultFramebufferObject(), int(std::lround(width() * dpr)), int(std::lround(height() * dpr)))) {
        ++stats_.paints;
        drawOverlays();
        emit statsChanged();
        return;
    }
    paintPreview();
}

void RenderView::showPreparationProgress(const QString& stage, int done, int total) {
    QString what = stage;
    if (stage == QLatin1String("meshes")) what = tr("building mesh BVHs");
    else if (stage == QLatin1String("textures")) what = tr("decoding textures");
    else if (stage == QLatin1String("environment")) what = tr("loading the environment");
    else if (stage == QLatin1String("packing")) what = tr("packing the scene");
    else if (stage == QLatin1String("picking")) what = tr("building the click picker");
    stats_.preparation = total > 1 ? tr("Preparing the scene: %1 %2/%3").arg(what).arg(done + 1).arg(total)
                                   : tr("Preparing the scene: %1").arg(what);
    emit statsChanged();
}

// Renderer warnings reach the log panel through the document, as the loader's do, each once per
// opened file (every preparation of the same scene reports the same ones).
void RenderView::reportRendererWarnings() {
    const QString file = document_.filePath().isEmpty() ? document_.displayName() : document_.filePath();
    for (const Warning& w : renderer_->warnings())
        if (reportedWarnings_.insert({w.code, w.message}).second)
            document_.reportWarning(QStringLiteral("%1: %2").arg(file, QString::fromStdString(w.message)));
}

void RenderView::configure(bool moving, int divisor) {
    const qreal dpr = devicePixelRatioF();
    const RenderSettings& project = document_.scene().settings.render;
    renderer::FrameSettings s = renderer_->settings();
    s.configuration = moving ? renderer::Configuration::Full : renderer::Configuration::Accumulate;
    s.spp = 1;
    s.maxSamples = std::max(1, project.spp);
    s.bounces = project.bounces;
    s.seed = project.seed;
    s.exposure = project.exposure;
    s.clamp = project.clamp;
    s.view = mode_ == ViewMode::AmbientOcclusion ? renderer::DebugView::AmbientOcclusion : renderer::DebugView::None;
    if (mode_ == ViewMode::BvhCost) { // counts: a plain mean, never reconstructed with history
        s.view = renderer::DebugView::BvhCost;
        s.configuration = renderer::Configuration::Accumulate;
    }
    s.region = region_.renderRegion();
    s.width = std::max(1, int(std::lround(width() * dpr)) / divisor);
    s.height = std::max(1, int(std::lround(height() * dpr)) / divisor);
    const renderer::FrameSettings& old = renderer_->settings();
    const bool same = old.configuration == s.configuration && old.spp == s.spp && old.maxSamples == s.maxSamples &&
                      old.bounces == s.bounces && old.seed == s.seed && old.exposure == s.exposure && old.clamp == s.clamp &&
                      old.view == s.view && old.width == s.width && old.height == s.height && old.region == s.region;
    if (!same) renderer_->setSettings(s);
    if (lookThrough_.valid() && document_.scene().contains(lookThrough_))
        renderer_->useSceneCamera(document_.scene().at(lookThrough_).name);
    else
        renderer_->setCamera(setupFrom(camera_, s.width, s.height));
}

bool RenderView::moving() const {
    return drag_ == Drag::Orbit || drag_ == Drag::Pan || drag_ == Drag::Zoom || drag_ == Drag::Fly ||
           drag_ == Drag::Gizmo || sinceMotion_.elapsed() < kSettleMs;
}

bool RenderView::converged() const {
    return renderer_->settings().configuration == renderer::Configuration::Accumulate &&
           renderer_->sampleCount() >= renderer_->settings().maxSamples;
}

void RenderView::renderSlice(bool moving, int divisor) {
    QElapsedTimer paint;
    paint.start();
    stats_.framesThisPaint = 0;
    double last = 0.0;
    do {
        QElapsedTimer frame;
        frame.start();
        renderer_->renderFrame();
        renderer::raster::finishGpuWork();
        last = double(frame.nsecsElapsed()) / 1e6;
        budget_.report(last, divisor, moving);
        ++stats_.framesThisPaint;
    } while (!moving && !converged() && budget_.anotherFits(double(paint.nsecsElapsed()) / 1e6, last));
    stats_.frameMs = last;
    stats_.paintMs = double(paint.nsecsElapsed()) / 1e6;
}

void RenderView::paintPreview() {
    if (previewStale_) {
        preview_->invalidate();
        previewStale_ = false;
    }
    const qreal dpr = devicePixelRatioF();
    renderer::raster::PreviewView v;
    v.width = int(std::lround(width() * dpr));
    v.height = int(std::lround(height() * dpr));
    v.clipFromWorld = clipFromWorld(camera_, double(width()) / std::max(1, height()));
    v.eye = glm::vec3(camera_.position());
    v.style = mode_ == ViewMode::Wireframe ? renderer::raster::PreviewStyle::Wireframe : renderer::raster::PreviewStyle::Solid;
    v.highlight = document_.currentNode();
    const Scene& scene = document_.scene();
    try {
        if (scene.animations.empty()) preview_->draw(scene, defaultFramebufferObject(), v);
        else preview_->draw(sceneAt(scene, document_.currentTime()), defaultFramebufferObject(), v);
    } catch (const std::exception& e) {
        stats_.error = QString::fromStdString(e.what());
    }
    picker(); // the raster views prepare no GPU scene: this starts a picker-only job where needed
    ++stats_.paints;
    drawOverlays();
    emit statsChanged();
}

void RenderView::paintGL() {
    if (!renderer_) return;
    if (showsRaster(mode_)) {
        paintPreview();
        return;
    }
    const bool isMoving = moving();
    // The still divisor is locked while the view rests (a change restarts accumulation), except
    // that an overrunning still frame may coarsen it at once.
    if (isMoving || stillDivisor_ == 0 || budget_.resolutionDivisor(false) > stillDivisor_)
        stillDivisor_ = budget_.resolutionDivisor(false);
    const int divisor = isMoving ? budget_.resolutionDivisor(true) : stillDivisor_;
    stats_.divisor = divisor;
    try {
        if (!syncGpuScene()) {
            paintWhilePreparing();
            return;
        }
        configure(isMoving, divisor);
        if (stats_.error.isEmpty() && !paused_ && !converged()) renderSlice(isMoving, divisor);
        const qreal dpr = devicePixelRatioF();
        renderer_->drawTo(defaultFramebufferObject(), int(std::lround(width() * dpr)), int(std::lround(height() * dpr)));
        readBack_ = showsReadBack(mode_) ? debugImage(renderer_->readImages(), mode_) : QImage();
    } catch (const std::exception& e) {
        stats_.error = QString::fromStdString(e.what());
    }
    stats_.samples = renderer_->sampleCount();
    ++stats_.paints;
    drawOverlays();
    emit statsChanged();
    if (isMoving) settleTimer_.start(kSettleMs);
    scheduleNextPaint();
}

void RenderView::scheduleNextPaint() {
    // Yield to the event loop between paints: the next slice is a queued update, not a loop.
    if (!paused_ && stats_.error.isEmpty() && !converged()) QTimer::singleShot(0, this, qOverload<>(&QWidget::update));
}

void RenderView::drawOverlays() {
    QPainter painter(this);
    if (!readBack_.isNull()) painter.drawImage(rect(), readBack_);
    if (comparing_ && !snapshot_.isNull()) {
        const int half = width() / 2;
        painter.drawImage(QRect(0, 0, half, height()), snapshot_, QRect(0, 0, snapshot_.width() / 2, snapshot_.height()));
        painter.setPen(QPen(Qt::white, 1));
        painter.drawLine(half, 0, half, height());
        painter.drawText(QRect(4, 4, half - 8, 20), Qt::AlignLeft, tr("A"));
        painter.drawText(QRect(half + 4, 4, half - 8, 20), Qt::AlignLeft, tr("B"));
    }
    OverlayPainter overlays(painter, *this, document_);
    if (mode_ == ViewMode::BvhBoxes) overlays.drawBoxes(picker().instanceBounds());
    if (mode_ == ViewMode::BvhCost && !readBack_.isNull()) overlays.drawCostLegend(readBack_.text(kCostScaleKey).toFloat());
    if (const auto frame = region_.frame(size()); frame && !showsRaster(mode_)) overlays.drawRegion(*frame);
    overlays.drawCameraPaths(lookThrough_);
    overlays.drawNodeIcons(picking_->icons(document_.scene(), document_.currentTime()), lookThrough_);
    if (const NodeId node = document_.currentNode(); node.valid() && document_.scene().contains(node))
        overlays.drawGizmo(gizmoFrame(node), gizmoMode_, gizmoDrag_ ? gizmoDrag_->axis() : -1);
    if (!stats_.error.isEmpty()) overlays.drawMessage(stats_.error);
    else if (!stats_.hint.isEmpty() && !showsRaster(mode_)) overlays.drawMessage(stats_.hint, OverlayPainter::MessageKind::Hint);
}

// Most glTF assets carry no light and the default environment is black: say why the image is.
void RenderView::noteLighting() {
    stats_.hint = hasLightSource(document_.scene())
                      ? QString()
                      : tr("Nothing in the scene emits light, so the path-traced image is black: add a light or an emissive "
                           "material, or give the environment a colour or an image (Scene tab).");
}

// --- camera and modes ----------------------------------------------------------------------

void RenderView::setCamera(const ViewCamera& camera) {
    camera_ = camera;
    noteMotion();
}

void RenderView::noteMotion() {
    sinceMotion_.restart();
    emit cameraMoved();
    update();
}

void RenderView::setMode(ViewMode mode) {
    mode_ = mode;
    update();
}

void RenderView::setGizmoMode(GizmoMode mode) {
    gizmoMode_ = mode;
    update();
}

void RenderView::setLookThrough(NodeId camera) {
    const NodeId previous = lookThrough_;
    lookThrough_ = camera;
    // Leaving a scene camera (or entering one): the viewport camera continues from its view.
    placeAtCamera(camera.valid() ? camera : previous);
    noteMotion();
}

void RenderView::followLookThrough() {
    if (lookThrough_.valid()) placeAtCamera(lookThrough_);
}

void RenderView::placeAtCamera(NodeId camera) {
    if (!camera.valid() || !document_.scene().contains(camera)) return;
    Scene storage;
    const Scene& posed = posedAt(document_.scene(), document_.currentTime(), storage);
    const auto* lens = posed.at(camera).get<Camera>();
    setFromWorld(camera_, posed.worldFromNode(camera), lens ? lens->yfov : camera_.yfov);
}

void RenderView::setPaused(bool paused) {
    paused_ = paused;
    update();
}

void RenderView::takeSnapshot() {
    snapshot_ = grabFramebuffer();
    update();
}

void RenderView::setComparing(bool on) {
    comparing_ = on;
    update();
}

void RenderView::armRenderRegion() {
    region_.arm();
    setCursor(Qt::CrossCursor);
}

void RenderView::setRenderRegion(const std::optional<QRectF>& fractions) {
    region_.cancel();
    unsetCursor();
    region_.setRegion(fractions);
    update();
}

// --- picking and framing -------------------------------------------------------------------

void RenderView::armFocusPick(bool on) {
    focusPickArmed_ = on;
    if (on) setCursor(Qt::CrossCursor);
    else unsetCursor();
}

const ScenePicker& RenderView::picker() {
    // The path-traced views get the picker with their GPU scene; the raster views prepare none.
    const bool preparationComing = preparer_->busy() || (!showsRaster(mode_) && renderer_ && stats_.error.isEmpty());
    return picking_->picker(document_.scene(), document_.currentTime(), preparationComing);
}

bvh::Ray RenderView::rayAt(QPointF p) const { return pixelRay(camera_, p.x(), p.y(), width(), height()); }

NodeId RenderView::pickAt(QPointF p) {
    const auto icons = projectIcons(picking_->icons(document_.scene(), document_.currentTime()), camera_, width(), height(), lookThrough_);
    if (const auto icon = nearestIcon(icons, {p.x(), p.y()}, kIconPickRadius)) return *icon;
    return picker().pick(rayAt(p)).node;
}

std::optional<QPointF> RenderView::project(const glm::dvec3& world) const {
    const glm::dvec3 p = projectToPixels(camera_, world, width(), height());
    if (p.z <= 0.0) return std::nullopt;
    return QPointF(p.x, p.y);
}

GizmoFrame RenderView::gizmoFrame(NodeId node) const {
    GizmoFrame frame;
    const glm::dmat4 world(document_.scene().worldFromNode(node));
    frame.origin = glm::dvec3(world[3]);
    if (gizmoMode_ == GizmoMode::Scale)
        for (int a = 0; a < 3; ++a) frame.axes[a] = glm::normalize(glm::dvec3(world[a]));
    frame.size = 0.15 * std::max(1e-3, glm::length(frame.origin - camera_.position())) * std::tan(0.5 * camera_.yfov) * 2.0;
    return frame;
}

void RenderView::frameSelection() {
    bvh::Aabb box;
    for (const NodeId id : document_.selection()) box.grow(picker().worldBounds(id));
    if (box.empty())
        for (const auto& [id, node] : document_.scene().nodes()) box.grow(picker().worldBounds(id));
    if (box.empty()) return;
    const glm::dvec3 centre(box.centre());
    const double radius = 0.5 * glm::length(glm::dvec3(box.extent()));
    frameSphere(camera_, centre, radius, double(width()) / std::max(1, height()));
    lookThrough_ = {};
    noteMotion();
}

void RenderView::selectAt(QPointF p, bool extend) {
    const NodeId hit = pickAt(p);
    std::vector<NodeId> selection = extend ? document_.selection() : std::vector<NodeId>{};
    if (hit.valid()) {
        std::erase(selection, hit);
        selection.push_back(hit);
    }
    document_.setSelection(selection);
}

void RenderView::inspectPixel(QPointF p) {
    if (!renderer_) return;
    makeCurrent();
    const renderer::FrameImages images = renderer_->readImages();
    doneCurrent();
    if (images.width <= 0 || images.height <= 0) return;
    const int x = std::clamp(int(p.x() * images.width / std::max(1, width())), 0, images.width - 1);
    const int y = std::clamp(int(p.y() * images.height / std::max(1, height())), 0, images.height - 1);
    const float* v = images.radiance.data() + 4 * (std::size_t(y) * std::size_t(images.width) + std::size_t(x));
    emit pixelInspected(QPoint(x, y), v[0], v[1], v[2], v[3]);
    QToolTip::showText(mapToGlobal(p.toPoint()), tr("Pixel %1, %2\nR %3  G %4  B %5 (linear)")
                                                     .arg(x).arg(y).arg(double(v[0]), 0, 'g', 5)
                                                     .arg(double(v[1]), 0, 'g', 5).arg(double(v[2]), 0, 'g', 5), this);
}

// --- input ---------------------------------------------------------------------------------

void RenderView::mousePressEvent(QMouseEvent* event) {
    lastMouse_ = pressMouse_ = event->position();
    if (event->button() == Qt::LeftButton && focusPickArmed_) {
        armFocusPick(false);
        emit focusClicked(event->position());
        return;
    }
    if (event->button() == Qt::LeftButton && region_.press(event->position())) return;
    const auto mods = event->modifiers();
    if (event->button() == Qt::LeftButton && !(mods & Qt::AltModifier)) {
        const NodeId node = document_.currentNode();
        if (node.valid() && document_.scene().contains(node) && !lookThrough_.valid()) {
            auto drag = std::make_unique<GizmoDrag>(document_, node, gizmoFrame(node), gizmoMode_, rayAt(event->position()));
            if (drag->active()) {
                gizmoDrag_ = std::move(drag);
                drag_ = Drag::Gizmo;
                return;
            }
        }
        drag_ = Drag::Click;
    } else if (event->button() == Qt::LeftButton || (event->button() == Qt::MiddleButton && !(mods & (Qt::ShiftModifier | Qt::ControlModifier)))) {
        drag_ = Drag::Orbit;
    } else if (event->button() == Qt::MiddleButton) {
        drag_ = (mods & Qt::ShiftModifier) ? Drag::Pan : Drag::Zoom;
    } else if (event->button() == Qt::RightButton) {
        drag_ = Drag::Fly;
        flyTimer_.start();
    }
    if (drag_ != Drag::Click && drag_ != Drag::Gizmo && lookThrough_.valid()) setLookThrough({});
}

void RenderView::mouseMoveEvent(QMouseEvent* event) {
    if (region_.move(event->position())) {
        update();
        return;
    }
    const QPointF d = event->position() - lastMouse_;
    lastMouse_ = event->position();
    switch (drag_) {
    case Drag::Orbit: orbit(camera_, d.x(), d.y()); break;
    case Drag::Pan: pan(camera_, d.x(), d.y(), height()); break;
    case Drag::Zoom: zoom(camera_, -d.y() / 20.0); break;
    case Drag::Fly: look(camera_, d.x(), d.y()); break;
    case Drag::Gizmo:
    {
        GizmoSnap snap = snap_; // Ctrl inverts snapping for this move
        snap.enabled = snap.enabled != bool(event->modifiers() & Qt::ControlModifier);
        gizmoDrag_->moveTo(rayAt(event->position()), snap);
    }
        sinceMotion_.restart();
        update();
        return;
    default: return;
    }
    noteMotion();
}

void RenderView::mouseReleaseEvent(QMouseEvent* event) {
    if (region_.release(event->position(), size())) {
        unsetCursor();
        update();
        return;
    }
    if (drag_ == Drag::Click) {
        const QPointF moved = event->position() - pressMouse_;
        if (std::hypot(moved.x(), moved.y()) <= kClickSlopPixels) {
            if (inspecting_) inspectPixel(event->position());
            else selectAt(event->position(), event->modifiers() & Qt::ShiftModifier);
        }
    }
    gizmoDrag_.reset();
    flyTimer_.stop();
    flyKeys_.clear();
    drag_ = Drag::None;
    update();
}

void RenderView::wheelEvent(QWheelEvent* event) {
    zoom(camera_, event->angleDelta().y() / 120.0);
    if (lookThrough_.valid()) setLookThrough({});
    noteMotion();
}

void RenderView::keyPressEvent(QKeyEvent* event) {
    if (drag_ == Drag::Fly && !event->isAutoRepeat()) {
        flyKeys_.insert(event->key());
        return;
    }
    if (event->key() == Qt::Key_Escape && region_.armed()) {
        setRenderRegion(region_.region()); // drops the armed drag, keeps the region
        return;
    }
    if (event->key() == Qt::Key_Escape && focusPickArmed_) {
        armFocusPick(false);
        return;
    }
    if (drag_ == Drag::Gizmo && event->key() == Qt::Key_Escape) {
        gizmoDrag_->cancel();
        gizmoDrag_.reset();
        drag_ = Drag::None;
        update();
        return;
    }
    switch (event->key()) {
    case Qt::Key_W: setGizmoMode(GizmoMode::Translate); break;
    case Qt::Key_E: setGizmoMode(GizmoMode::Rotate); break;
    case Qt::Key_R: setGizmoMode(GizmoMode::Scale); break;
    default: QOpenGLWidget::keyPressEvent(event);
    }
}

void RenderView::keyReleaseEvent(QKeyEvent* event) {
    if (!event->isAutoRepeat()) flyKeys_.erase(event->key());
    QOpenGLWidget::keyReleaseEvent(event);
}

void RenderView::focusOutEvent(QFocusEvent* event) {
    flyKeys_.clear();
    QOpenGLWidget::focusOutEvent(event);
}

void RenderView::flyStep() {
    glm::dvec3 move(0.0);
    const auto held = [&](int key) { return flyKeys_.count(key) != 0; };
    move.z += held(Qt::Key_W) - held(Qt::Key_S);
    move.x += held(Qt::Key_D) - held(Qt::Key_A);
    move.y += held(Qt::Key_E) - held(Qt::Key_Q);
    if (move == glm::dvec3(0.0)) return;
    // Speed follows the orbit distance: a metre is slow in a city and fast on a table.
    const double speed = std::max(0.1, camera_.distance) * kFlyIntervalMs / 1000.0;
    fly(camera_, move * speed);
    noteMotion();
}

} // namespace glint::editor
