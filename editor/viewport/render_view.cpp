// The renderer's GL headers (epoxy) come before any Qt OpenGL header in this translation unit.
#include "renderer/frame_renderer.h"

#include "editor/viewport/render_view.h"

#include "editor/document/document.h"
#include "editor/viewport/initial_view.h"
#include "editor/viewport/scene_picker.h"
#include "editor/viewport/view_picking.h"
#include "scene/anim/scene_at_time.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QToolTip>
#include <QWheelEvent>

#include <cmath>

namespace glint::editor {

namespace {

constexpr int kSettleMs = 150; // the view counts as moving this long after the last change

} // namespace

RenderView::RenderView(Document& document, QWidget* parent)
    : QOpenGLWidget(parent), document_(document), host_(document), tools_(*this, document), overlays_(*this, document) {
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(true);
    setAccessibleName(tr("Viewport"));
    setMinimumSize(64, 64);
    settleTimer_.setSingleShot(true);
    connect(&settleTimer_, &QTimer::timeout, this, qOverload<>(&QWidget::update));
    connect(&host_, &RenderHost::paintRequested, this, qOverload<>(&QWidget::update));
    connect(&host_, &RenderHost::statsChanged, this, &RenderView::statsChanged);
    connect(&tools_, &ViewTools::clicked, this, &RenderView::selectAt);
    connect(&tools_, &ViewTools::inspected, this, &RenderView::inspectPixel);
    connect(&tools_, &ViewTools::focusClicked, this, &RenderView::focusClicked);
    connect(&document_, &Document::changed, this, &RenderView::followLookThrough);
    connect(&document_, &Document::timeChanged, this, &RenderView::followLookThrough);
    connect(&document_, &Document::selectionChanged, this, qOverload<>(&QWidget::update));
    connect(&document_, &Document::sceneReplaced, this, [this] {
        lookThrough_ = {};
        setCamera(initialView(document_.scene(), double(width()) / std::max(1, height())));
    });
    sinceMotion_.invalidate(); // a view that opens is still: it refines at full resolution at once
    document_.setViewFocusProvider([this] { return focus(); });
}

RenderView::~RenderView() {
    document_.setViewFocusProvider({});
    if (!context()) return;
    // The context dies in QOpenGLWidget's destructor, after the host: release the GL objects now.
    disconnect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &RenderView::releaseGl);
    if (host_.hasGl()) releaseGl();
}

void RenderView::releaseGl() {
    // The context is about to go (re-docking, floating, closing): GL objects die with it.
    makeCurrent();
    host_.releaseGl();
    doneCurrent();
}

void RenderView::initializeGL() {
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &RenderView::releaseGl, Qt::UniqueConnection);
    host_.initializeGl();
}

void RenderView::resizeGL(int, int) { update(); }

bool RenderView::moving() const {
    return tools_.navigating() || (sinceMotion_.isValid() && sinceMotion_.elapsed() < kSettleMs);
}

void RenderView::paintGL() {
    const qreal dpr = devicePixelRatioF();
    ViewRequest request;
    request.mode = mode_;
    request.camera = &camera_;
    request.lookThrough = lookThrough_.valid() && document_.scene().contains(lookThrough_) ? lookThrough_ : NodeId{};
    request.width = int(std::lround(width() * dpr));
    request.height = int(std::lround(height() * dpr));
    request.aspect = double(width()) / std::max(1, height());
    request.moving = moving();
    request.region = tools_.region().renderRegion();
    host_.paint(request, defaultFramebufferObject());
    overlays_.draw(host_, tools_, mode_, lookThrough_);
    if (request.moving) settleTimer_.start(kSettleMs);
}

// --- camera and modes ----------------------------------------------------------------------

void RenderView::setCamera(const ViewCamera& camera) {
    camera_ = camera;
    noteMotion(true);
}

void RenderView::noteMotion(bool cameraChanged) {
    sinceMotion_.restart();
    if (cameraChanged) emit cameraMoved();
    update();
}

void RenderView::setMode(ViewMode mode) {
    mode_ = mode;
    update();
}

void RenderView::setLookThrough(NodeId camera) {
    const NodeId previous = lookThrough_;
    lookThrough_ = camera;
    // Leaving a scene camera (or entering one): the viewport camera continues from its view.
    placeAtCamera(camera.valid() ? camera : previous);
    noteMotion(true);
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

void RenderView::takeSnapshot() {
    overlays_.takeSnapshot(grabFramebuffer());
    update();
}

void RenderView::setComparing(bool on) {
    overlays_.setComparing(on);
    update();
}

// --- picking and framing -------------------------------------------------------------------

const ScenePicker& RenderView::picker() { return host_.picker(mode_); }

bvh::Ray RenderView::rayAt(QPointF p) const { return pixelRay(camera_, p.x(), p.y(), width(), height()); }

NodeId RenderView::pickAt(QPointF p) {
    const auto icons = projectIcons(picking().icons(document_.scene(), document_.currentTime()), camera_, width(), height(), lookThrough_);
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
    Scene storage; // where the node is shown: a keyed node's pose at the current time
    const glm::dmat4 world(posedAt(document_.scene(), document_.currentTime(), storage).worldFromNode(node));
    frame.origin = glm::dvec3(world[3]);
    if (tools_.gizmoMode() == GizmoMode::Scale || tools_.gizmoSpace() == GizmoSpace::Local)
        for (int a = 0; a < 3; ++a) frame.axes[a] = glm::normalize(glm::dvec3(world[a]));
    frame.size = 0.15 * std::max(1e-3, glm::length(frame.origin - camera_.position())) * std::tan(0.5 * camera_.yfov) * 2.0;
    return frame;
}

ViewFocus RenderView::focus() {
    ViewFocus f;
    f.point = camera_.target;
    bvh::Aabb scene;
    for (const bvh::Aabb& box : picker().instanceBounds()) scene.grow(box);
    const double reach = 2.0 * camera_.distance;
    f.scale = scene.empty() ? reach : std::min(reach, double(glm::length(scene.extent())));
    // Straight up to the first surface over the focus, past objects whose bounds hold the point the
    // ray starts from (the focus inside a shape just added there): their tops are where it is clear.
    glm::vec3 from(f.point);
    for (int passed = 0; passed < 8; ++passed) {
        const PickResult above = picker().pick({from, glm::vec3(0.0f, 1.0f, 0.0f)});
        if (!above.node.valid()) break;
        const bvh::Aabb box = picker().worldBounds(above.node);
        const bool around = glm::all(glm::greaterThanEqual(from, box.lo)) && glm::all(glm::lessThanEqual(from, box.hi));
        if (!around) {
            f.headroom = double(from.y) - f.point.y + above.t;
            break;
        }
        from.y = box.hi.y + 1e-3f * std::max(1.0f, std::abs(box.hi.y));
        f.clearFrom = double(from.y) - f.point.y;
    }
    const PickResult below = picker().pick({glm::vec3(f.point), glm::vec3(0.0f, -1.0f, 0.0f)});
    if (below.node.valid()) f.floor = below.t;
    return f;
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
    noteMotion(true);
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
    if (!host_.hasGl()) return;
    makeCurrent();
    const renderer::FrameImages images = host_.readImages();
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

// --- input: the tools' state machine ---------------------------------------------------------

void RenderView::mousePressEvent(QMouseEvent* event) { tools_.press(event); }
void RenderView::mouseMoveEvent(QMouseEvent* event) { tools_.move(event); }
void RenderView::mouseReleaseEvent(QMouseEvent* event) { tools_.release(event); }
void RenderView::wheelEvent(QWheelEvent* event) { tools_.wheel(event); }

void RenderView::keyPressEvent(QKeyEvent* event) {
    if (!tools_.keyPress(event)) QOpenGLWidget::keyPressEvent(event);
}

void RenderView::keyReleaseEvent(QKeyEvent* event) {
    tools_.keyRelease(event);
    QOpenGLWidget::keyReleaseEvent(event);
}

void RenderView::focusOutEvent(QFocusEvent* event) {
    tools_.focusOut();
    QOpenGLWidget::focusOutEvent(event);
}

void RenderView::changeEvent(QEvent* event) {
    QOpenGLWidget::changeEvent(event);
    if (event->type() != QEvent::LanguageChange) return;
    host_.noteLighting();
    emit statsChanged();
    update();
}

} // namespace glint::editor
