#include "editor/viewport/viewport.h"

#include "editor/document/document.h"
#include "editor/preferences/retranslate.h"
#include "editor/viewport/focus_pick.h"
#include "editor/viewport/render_view.h"
#include "scene/history/node_commands.h"

#include <QAction>
#include <QActionGroup>
#include <QMainWindow>
#include <QStatusBar>
#include <QVBoxLayout>

namespace glint::editor {

namespace {

// The view modes' names, untranslated (they follow language changes: retranslate.h).
const char* modeName(ViewMode mode) {
    switch (mode) {
    case ViewMode::PathTraced: return QT_TRANSLATE_NOOP("glint::editor::Viewport", "Path traced");
    case ViewMode::Solid: return QT_TRANSLATE_NOOP("glint::editor::Viewport", "Solid");
    case ViewMode::Wireframe: return QT_TRANSLATE_NOOP("glint::editor::Viewport", "Wireframe");
    case ViewMode::Normals: return QT_TRANSLATE_NOOP("glint::editor::Viewport", "Normals");
    case ViewMode::Albedo: return QT_TRANSLATE_NOOP("glint::editor::Viewport", "Albedo");
    case ViewMode::AmbientOcclusion: return QT_TRANSLATE_NOOP("glint::editor::Viewport", "Ambient occlusion");
    case ViewMode::Motion: return QT_TRANSLATE_NOOP("glint::editor::Viewport", "Motion vectors");
    case ViewMode::Variance: return QT_TRANSLATE_NOOP("glint::editor::Viewport", "Variance");
    case ViewMode::Depth: return QT_TRANSLATE_NOOP("glint::editor::Viewport", "Depth");
    case ViewMode::BvhBoxes: return QT_TRANSLATE_NOOP("glint::editor::Viewport", "BVH instance boxes");
    case ViewMode::BvhCost: return QT_TRANSLATE_NOOP("glint::editor::Viewport", "BVH traversal cost (heat map)");
    }
    return "";
}

// Stable ids for the keymap (preferences store shortcuts by object name).
const char* modeId(ViewMode mode) {
    switch (mode) {
    case ViewMode::PathTraced: return "view.mode.pathTraced";
    case ViewMode::Solid: return "view.mode.solid";
    case ViewMode::Wireframe: return "view.mode.wireframe";
    case ViewMode::Normals: return "view.mode.normals";
    case ViewMode::Albedo: return "view.mode.albedo";
    case ViewMode::AmbientOcclusion: return "view.mode.ambientOcclusion";
    case ViewMode::Motion: return "view.mode.motion";
    case ViewMode::Variance: return "view.mode.variance";
    case ViewMode::Depth: return "view.mode.depth";
    case ViewMode::BvhBoxes: return "view.mode.bvhBoxes";
    case ViewMode::BvhCost: return "view.mode.bvhCost";
    }
    return "";
}

// An action whose text follows the language; `text` is its source in the Viewport context.
QAction* translatedAction(QObject* parent, const char* text) {
    auto* action = new QAction(parent);
    keepTranslated(action, TextRole::Text, Viewport::staticMetaObject.className(), text);
    return action;
}

QAction* checkable(QObject* parent, const char* text, const QKeySequence& key) {
    auto* action = translatedAction(parent, text);
    action->setCheckable(true);
    action->setShortcut(key);
    action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    return action;
}

} // namespace

Viewport::Viewport(Document& document, QWidget* parent) : QWidget(parent), document_(document) {
    keepTranslated(this, TextRole::AccessibleName, staticMetaObject.className(), QT_TR_NOOP("Viewport"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    view_ = new RenderView(document, this);
    layout->addWidget(view_);
    createActions();
    connect(view_, &RenderView::statsChanged, this, [this] { emit statusMessage(statusText()); });
}

void Viewport::createActions() {
    modes_ = new QActionGroup(this);
    int number = 1;
    for (const ViewMode mode : kViewModes) {
        // Number keys 1..9 for the first nine views (0 is "look through").
        const QKeySequence key = number <= 9 ? QKeySequence(Qt::Key_0 + number) : QKeySequence();
        ++number;
        QAction* action = checkable(this, modeName(mode), key);
        action->setChecked(mode == ViewMode::PathTraced);
        action->setData(int(mode));
        action->setObjectName(modeId(mode));
        modes_->addAction(action);
        addAction(action);
        connect(action, &QAction::triggered, this, [this, mode] { view_->setMode(mode); });
    }

    gizmos_ = new QActionGroup(this);
    const std::pair<GizmoMode, const char*> gizmoModes[] = {{GizmoMode::Translate, QT_TR_NOOP("Move")},
                                                            {GizmoMode::Rotate, QT_TR_NOOP("Rotate")},
                                                            {GizmoMode::Scale, QT_TR_NOOP("Scale")}};
    const Qt::Key gizmoKeys[] = {Qt::Key_W, Qt::Key_E, Qt::Key_R};
    const char* gizmoIds[] = {"view.gizmo.move", "view.gizmo.rotate", "view.gizmo.scale"};
    for (int i = 0; i < 3; ++i) {
        const GizmoMode mode = gizmoModes[i].first;
        QAction* action = checkable(this, gizmoModes[i].second, QKeySequence(gizmoKeys[i]));
        action->setShortcut({}); // the view handles W/E/R itself so that fly navigation can use them
        action->setChecked(i == 0);
        action->setObjectName(gizmoIds[i]);
        action->setData(int(mode));
        gizmos_->addAction(action);
        connect(action, &QAction::triggered, this, [this, mode] { view_->setGizmoMode(mode); });
    }
    connect(&view_->tools(), &ViewTools::gizmoModeChanged, this, [this](GizmoMode mode) {
        for (QAction* action : gizmos_->actions()) action->setChecked(action->data().toInt() == int(mode));
    });

    frameSelection_ = translatedAction(this, QT_TR_NOOP("Frame selection"));
    frameSelection_->setShortcut(Qt::Key_F);
    frameSelection_->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    addAction(frameSelection_);
    connect(frameSelection_, &QAction::triggered, view_, &RenderView::frameSelection);

    makeSceneCamera_ = translatedAction(this, QT_TR_NOOP("Make scene camera from view"));
    connect(makeSceneCamera_, &QAction::triggered, this, &Viewport::makeSceneCamera);

    lookThrough_ = checkable(this, QT_TR_NOOP("Look through selected camera"), QKeySequence(Qt::Key_0));
    addAction(lookThrough_);
    connect(lookThrough_, &QAction::triggered, this, &Viewport::toggleLookThrough);

    localAxes_ = checkable(this, QT_TR_NOOP("Local axes"), QKeySequence(Qt::Key_L));
    keepTranslated(localAxes_, TextRole::ToolTip, staticMetaObject.className(),
                   QT_TR_NOOP("Move and rotate along the selected node's own axes (off: the world's)"));
    addAction(localAxes_);
    connect(localAxes_, &QAction::toggled, this, [this](bool on) { view_->setGizmoSpace(on ? GizmoSpace::Local : GizmoSpace::World); });

    snap_ = checkable(this, QT_TR_NOOP("Snap (Ctrl inverts while dragging)"), QKeySequence());
    connect(snap_, &QAction::toggled, this, [this](bool on) { view_->snap().enabled = on; });

    inspect_ = checkable(this, QT_TR_NOOP("Pixel inspector"), QKeySequence(Qt::Key_I));
    addAction(inspect_);
    connect(inspect_, &QAction::toggled, view_, &RenderView::setInspecting);

    snapshot_ = translatedAction(this, QT_TR_NOOP("Take snapshot A"));
    connect(snapshot_, &QAction::triggered, this, [this] {
        view_->takeSnapshot();
        compare_->setEnabled(true);
    });
    renderRegion_ = translatedAction(this, QT_TR_NOOP("Set render region"));
    keepTranslated(renderRegion_, TextRole::ToolTip, staticMetaObject.className(), QT_TR_NOOP("Drag a rectangle: the path tracer renders only inside it"));
    renderRegion_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_B));
    renderRegion_->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    addAction(renderRegion_);
    connect(renderRegion_, &QAction::triggered, view_, &RenderView::armRenderRegion);
    clearRenderRegion_ = translatedAction(this, QT_TR_NOOP("Clear render region"));
    clearRenderRegion_->setShortcut(QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_B));
    clearRenderRegion_->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    addAction(clearRenderRegion_);
    connect(clearRenderRegion_, &QAction::triggered, this, [this] { view_->setRenderRegion(std::nullopt); });

    pause_ = checkable(this, QT_TR_NOOP("Pause viewport rendering"), QKeySequence());
    keepTranslated(pause_, TextRole::ToolTip, staticMetaObject.className(),
                   QT_TR_NOOP("Stop adding samples; edits are still shown at full resolution"));
    connect(pause_, &QAction::toggled, this, [this] { view_->setPaused(pause_->isChecked() || exportRunning_); });

    denoise_ = checkable(this, QT_TR_NOOP("Denoise still image"), QKeySequence());
    keepTranslated(denoise_, TextRole::ToolTip, staticMetaObject.className(),
                   QT_TR_NOOP("Filter the accumulated image while it converges (off: the raw running mean; renders are never filtered)"));
    denoise_->setChecked(true);
    connect(denoise_, &QAction::toggled, view_, &RenderView::setDenoise);

    compare_ = checkable(this, QT_TR_NOOP("Compare A | B"), QKeySequence());
    compare_->setEnabled(false);
    connect(compare_, &QAction::toggled, view_, &RenderView::setComparing);
    createPickFocusAction();
    const std::pair<QAction*, const char*> ids[] = {
        {frameSelection_, "view.frameSelection"}, {makeSceneCamera_, "view.makeSceneCamera"}, {lookThrough_, "view.lookThrough"},
        {snap_, "view.snap"}, {localAxes_, "view.localAxes"}, {inspect_, "view.inspect"}, {snapshot_, "view.snapshot"}, {compare_, "view.compare"},
        {renderRegion_, "view.renderRegion"}, {clearRenderRegion_, "view.clearRenderRegion"}, {pickFocus_, "view.pickFocus"},
        {pause_, "view.pause"}, {denoise_, "view.denoise"}};
    for (const auto& [action, id] : ids) action->setObjectName(id);
}

void Viewport::createPickFocusAction() {
    pickFocus_ = translatedAction(this, QT_TR_NOOP("Pick focus distance"));
    keepTranslated(pickFocus_, TextRole::ToolTip, staticMetaObject.className(), QT_TR_NOOP("Click a surface: the camera looked through focuses at its depth"));
    pickFocus_->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F));
    pickFocus_->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    addAction(pickFocus_);
    connect(pickFocus_, &QAction::triggered, this, [this] {
        if (!view_->lookThrough().valid()) {
            showHint(tr("Pick focus works through a scene camera: select one and look through it (0) first."));
            return;
        }
        view_->armFocusPick(true);
        showHint(tr("Click the surface to focus on (Esc cancels)."));
    });
    connect(view_, &RenderView::focusClicked, this, [this](QPointF at) { showHint(pickFocus(document_, *view_, at)); });
}

// Hints go to the window's status bar; the viewport's own status line shows render progress.
void Viewport::showHint(const QString& text) {
    if (auto* main = qobject_cast<QMainWindow*>(window())) main->statusBar()->showMessage(text, 8000);
    emit hint(text);
}

QList<QAction*> Viewport::viewModeActions() const { return modes_->actions(); }
QList<QAction*> Viewport::gizmoActions() const { return gizmos_->actions(); }

QList<QAction*> Viewport::allActions() const {
    QList<QAction*> all = viewModeActions();
    all << gizmoActions() << localAxes_ << frameSelection_ << makeSceneCamera_ << lookThrough_ << snap_ << inspect_ << snapshot_ << compare_ << renderRegion_
        << clearRenderRegion_ << pickFocus_ << pause_ << denoise_;
    return all;
}

void Viewport::setPaused(bool paused) {
    exportRunning_ = paused;
    view_->setPaused(paused || pause_->isChecked());
}

void Viewport::setSampleCap(int samples) { view_->setSampleCap(samples); }

NodeId Viewport::makeSceneCamera() {
    const ViewCamera& view = view_->camera();
    Node node;
    node.name = "Camera";
    node.local.translation = glm::vec3(view.position());
    node.local.rotation = glm::quat(view.orientation());
    Camera camera;
    camera.yfov = view.yfov;
    camera.focusDistance = static_cast<float>(view.distance);
    node.component = camera;
    auto command = std::make_unique<AddNode>(std::move(node));
    AddNode* add = command.get();
    document_.push(std::move(command));
    const NodeId id = add->nodeId();
    document_.setSelection({id});
    return id;
}

void Viewport::toggleLookThrough() {
    const NodeId current = document_.currentNode();
    const bool isCamera = current.valid() && document_.scene().contains(current) && document_.scene().at(current).get<Camera>();
    if (view_->lookThrough().valid() || !isCamera) {
        view_->setLookThrough({});
        lookThrough_->setChecked(false);
        return;
    }
    view_->setLookThrough(current);
    lookThrough_->setChecked(true);
}

QString Viewport::statusText() const {
    const ViewportStats& s = view_->stats();
    if (!s.error.isEmpty()) return s.error;
    if (s.preparing) return s.preparation;
    QString stage;
    switch (s.stage) {
    case ViewStage::Preparing: return s.preparation;
    case ViewStage::Coarse: stage = tr("coarse (1/%1 resolution)").arg(s.divisor); break;
    case ViewStage::Refining: stage = tr("refining to full resolution: %1%").arg(s.refinePercent); break;
    case ViewStage::Accumulating:
        stage = s.sampleCap > 0 ? tr("%1 / %2 spp").arg(s.samples).arg(s.sampleCap) : tr("%1 spp").arg(s.samples);
        if (s.convergedPercent >= 0) stage = tr("%1, %2% converged").arg(stage).arg(s.convergedPercent);
        break;
    case ViewStage::Converged: stage = tr("%1 spp, converged (viewport sample cap)").arg(s.samples); break;
    case ViewStage::NoiseConverged: stage = tr("up to %1 spp, converged (noise threshold)").arg(s.samples); break;
    case ViewStage::Paused: stage = tr("%1 spp, paused").arg(s.samples); break;
    }
    return tr("%1  |  %2 ms/frame").arg(stage).arg(s.frameMs, 0, 'f', 1);
}

} // namespace glint::editor
