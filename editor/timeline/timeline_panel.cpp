#include "editor/timeline/timeline_panel.h"

#include "editor/document/document.h"
#include "editor/outliner/node_names.h"
#include "editor/preferences/retranslate.h"
#include "editor/timeline/time_ruler.h"
#include "scene/anim/node_keys.h"
#include "scene/history/camera_path_commands.h"

#include <QAction>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QToolBar>
#include <QVBoxLayout>

#include <cmath>
#include <numbers>

namespace glint::editor {

namespace {

constexpr double kDegrees = 180.0 / std::numbers::pi;

} // namespace

TimelinePanel::TimelinePanel(Document& document, QWidget* parent) : QWidget(parent), document_(document) {
    keepTranslated(this, TextRole::AccessibleName, staticMetaObject.className(), QT_TR_NOOP("Timeline"));
    createActions();
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    auto* bar = new QToolBar(this);
    cameras_ = new QComboBox(bar);
    keepTranslated(cameras_, TextRole::AccessibleName, staticMetaObject.className(), QT_TR_NOOP("Path camera"));
    bar->addWidget(cameras_);
    bar->addActions({addKey_, deleteKey_});
    bar->addSeparator();
    bar->addActions({play_, loop_, constantSpeed_});
    bar->addSeparator();
    bar->addActions({keyNode_, autoKey_, copyNodeKey_, pasteNodeKey_});
    bar->addWidget(createInterpolationBox(bar));
    timeLabel_ = new QLabel(bar);
    bar->addWidget(timeLabel_);
    layout->addWidget(bar);
    ruler_ = new TimeRuler(document, this);
    layout->addWidget(ruler_);
    tracks_ = new NodeKeyTracks(document, *ruler_, this);
    layout->addWidget(tracks_);
    layout->addWidget(createKeyEditor());

    timer_.setTimerType(Qt::PreciseTimer);
    connect(&timer_, &QTimer::timeout, this, &TimelinePanel::stepFrame);
    connect(cameras_, &QComboBox::activated, this, [this](int i) { setCamera(NodeId{cameras_->itemData(i).toUInt()}); });
    connect(ruler_, &TimeRuler::keySelected, this, [this](std::optional<std::size_t> key) {
        if (key) tracks_->setSelectedKey(std::nullopt); // one selected key at a time: Delete acts on it
        refreshKeyEditor();
    });
    connect(tracks_, &NodeKeyTracks::keySelected, this, [this](std::optional<NodeKey> key) {
        copyNodeKey_->setEnabled(key.has_value());
        if (key) ruler_->setSelectedKey(std::nullopt);
        refreshKeyEditor();
    });
    connect(&document_, &Document::changed, this, [this] {
        refreshCameras();
        refreshKeyEditor();
        refreshInterpolation();
    });
    connect(&document_, &Document::fileChanged, this, [this] { refreshCameras(); });
    connect(&document_, &Document::selectionChanged, this, [this] {
        refreshInterpolation();
        const NodeId node = document_.currentNode();
        if (node.valid() && document_.scene().contains(node) && document_.scene().at(node).get<Camera>()) setCamera(node);
    });
    connect(&document_, &Document::timeChanged, this, [this](double t) {
        timeLabel_->setText(tr("  %1 s  (frame %2)").arg(t, 0, 'f', 3).arg(std::lround((t - document_.scene().settings.timeline.start) * fps())));
    });
    refreshCameras();
    refreshKeyEditor();
    refreshInterpolation();
}

void TimelinePanel::createActions() {
    createNodeKeyActions();
    addKey_ = new QAction(this);
    keepTranslated(addKey_, TextRole::Text, staticMetaObject.className(), QT_TR_NOOP("Add key"));
    keepTranslated(addKey_, TextRole::ToolTip, staticMetaObject.className(),
                   QT_TR_NOOP("Add a camera-path key from the current view at the current time"));
    connect(addKey_, &QAction::triggered, this, &TimelinePanel::addKey);
    deleteKey_ = new QAction(this);
    keepTranslated(deleteKey_, TextRole::Text, staticMetaObject.className(), QT_TR_NOOP("Delete key"));
    connect(deleteKey_, &QAction::triggered, this, &TimelinePanel::deleteKey);
    play_ = new QAction(this);
    keepTranslated(play_, TextRole::Text, staticMetaObject.className(), QT_TR_NOOP("Play"));
    play_->setCheckable(true);
    play_->setShortcut(Qt::Key_Space);
    play_->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    addAction(play_);
    connect(play_, &QAction::toggled, this, &TimelinePanel::setPlaying);
    loop_ = new QAction(this);
    keepTranslated(loop_, TextRole::Text, staticMetaObject.className(), QT_TR_NOOP("Loop"));
    loop_->setCheckable(true);
    loop_->setChecked(true);
    constantSpeed_ = new QAction(this);
    keepTranslated(constantSpeed_, TextRole::Text, staticMetaObject.className(), QT_TR_NOOP("Constant speed"));
    constantSpeed_->setCheckable(true);
    connect(constantSpeed_, &QAction::triggered, this, [this](bool on) {
        const CameraPath* p = path();
        if (!p || p->constantSpeed == on) return;
        document_.push(std::make_unique<SetCameraPathMode>(camera_, p->rotation, on));
    });
}

void TimelinePanel::createNodeKeyActions() {
    keyNode_ = new QAction(this);
    keepTranslated(keyNode_, TextRole::Text, staticMetaObject.className(), QT_TR_NOOP("Key transform"));
    keepTranslated(keyNode_, TextRole::ToolTip, staticMetaObject.className(),
                   QT_TR_NOOP("Key the selected nodes' position, rotation and scale at the current time (K)"));
    keyNode_->setShortcut(Qt::Key_K); // I (Blender's) is the pixel inspector here
    keyNode_->setShortcutContext(Qt::WindowShortcut);
    keyNode_->setObjectName("timeline.keyNode");
    connect(keyNode_, &QAction::triggered, this, [this] { keyNodes(document_, document_.selection(), document_.currentTime()); });
    autoKey_ = new QAction(this);
    keepTranslated(autoKey_, TextRole::Text, staticMetaObject.className(), QT_TR_NOOP("Auto key"));
    keepTranslated(autoKey_, TextRole::ToolTip, staticMetaObject.className(),
                   QT_TR_NOOP("Key every moved, turned or scaled node at the current time (nodes with keys are always keyed)"));
    autoKey_->setCheckable(true);
    autoKey_->setObjectName("timeline.autoKey");
    connect(autoKey_, &QAction::toggled, &document_, &Document::setAutoKey);
    connect(&document_, &Document::autoKeyChanged, autoKey_, &QAction::setChecked);
    copyNodeKey_ = new QAction(this);
    keepTranslated(copyNodeKey_, TextRole::Text, staticMetaObject.className(), QT_TR_NOOP("Copy key"));
    copyNodeKey_->setShortcut(QKeySequence::Copy);
    copyNodeKey_->setEnabled(false); // until a node key is selected
    copyNodeKey_->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    addAction(copyNodeKey_);
    connect(copyNodeKey_, &QAction::triggered, this, [this] {
        if (tracks_->selectedKey()) copied_ = tracks_->selectedKey();
        pasteNodeKey_->setEnabled(copied_.has_value());
    });
    pasteNodeKey_ = new QAction(this);
    keepTranslated(pasteNodeKey_, TextRole::Text, staticMetaObject.className(), QT_TR_NOOP("Paste key"));
    keepTranslated(pasteNodeKey_, TextRole::ToolTip, staticMetaObject.className(),
                   QT_TR_NOOP("Key the selected nodes at the current time with the copied key's transform"));
    pasteNodeKey_->setShortcut(QKeySequence::Paste);
    pasteNodeKey_->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    pasteNodeKey_->setEnabled(false);
    addAction(pasteNodeKey_);
    connect(pasteNodeKey_, &QAction::triggered, this, [this] {
        if (!copied_) return;
        for (const NodeId node : document_.selection()) pasteNodeKey(document_, *copied_, node, document_.currentTime());
    });
}

// Step, linear or cubic for the current node's row (glTF interpolates per channel, so per row).
QWidget* TimelinePanel::createInterpolationBox(QWidget* parent) {
    interpolation_ = new QComboBox(parent);
    keepTranslated(interpolation_, TextRole::AccessibleName, staticMetaObject.className(), QT_TR_NOOP("Interpolation"));
    interpolation_->addItem(tr("Step"), int(Interpolation::Step));
    interpolation_->addItem(tr("Linear"), int(Interpolation::Linear));
    interpolation_->addItem(tr("Cubic"), int(Interpolation::CubicSpline));
    connect(interpolation_, &QComboBox::activated, this, [this](int i) {
        setNodeInterpolation(document_, document_.currentNode(), interpolation_->itemData(i).toInt());
    });
    return interpolation_;
}

void TimelinePanel::refreshInterpolation() {
    const Scene& scene = document_.scene();
    const NodeId node = document_.currentNode();
    const std::optional<AnimationId> id = node.valid() && scene.contains(node) ? nodeKeyAnimation(scene, node) : std::nullopt;
    QSignalBlocker block(interpolation_);
    interpolation_->setEnabled(id.has_value());
    const Interpolation shown = id ? nodeKeyInterpolation(scene.animations.at(*id), node) : Interpolation::Linear; // a new row's
    interpolation_->setCurrentIndex(interpolation_->findData(int(shown)));
    keyNode_->setEnabled(!document_.selection().empty());
}

QWidget* TimelinePanel::createKeyEditor() {
    auto* editor = new QWidget(this);
    auto* row = new QHBoxLayout(editor);
    row->setContentsMargins(0, 0, 0, 0);
    const char* const sources[7] = {QT_TR_NOOP("X"), QT_TR_NOOP("Y"), QT_TR_NOOP("Z"), QT_TR_NOOP("FOV"),
                                    QT_TR_NOOP("Focus"), QT_TR_NOOP("Lens"), QT_TR_NOOP("Time")};
    for (int i = 0; i < 7; ++i) {
        auto* field = new QDoubleSpinBox(editor);
        field->setAccessibleName(tr("Key %1").arg(tr(sources[i])));
        field->setDecimals(i == 3 ? 2 : 4);
        field->setRange(i == 3 ? 0.1 : (i >= 4 ? 0.0 : -1e6), i == 3 ? 179.0 : 1e6);
        field->setKeyboardTracking(false);
        auto* label = new QLabel(editor);
        keepTranslated(label, TextRole::Text, staticMetaObject.className(), sources[i]);
        row->addWidget(label);
        row->addWidget(field);
        keyFields_[i] = field;
        if (i == 6) field->setReadOnly(true); // times change by dragging the key (MoveCameraKey)
        else connect(field, &QDoubleSpinBox::valueChanged, this, &TimelinePanel::editSelectedKey);
    }
    return editor;
}

double TimelinePanel::fps() const {
    const auto& t = document_.scene().settings.timeline;
    return t.fpsDenominator > 0 && t.fpsNumerator > 0 ? double(t.fpsNumerator) / t.fpsDenominator : 24.0;
}

const CameraPath* TimelinePanel::path() const {
    if (!camera_.valid() || !document_.scene().contains(camera_)) return nullptr;
    const auto* c = document_.scene().at(camera_).get<Camera>();
    return c ? &c->path : nullptr;
}

void TimelinePanel::setCamera(NodeId camera) {
    if (camera == camera_) return;
    camera_ = camera;
    ruler_->setCamera(camera);
    refreshCameras();
    refreshKeyEditor();
}

void TimelinePanel::refreshCameras() {
    const Scene& scene = document_.scene();
    if (camera_.valid() && !(scene.contains(camera_) && scene.at(camera_).get<Camera>())) camera_ = {};
    QSignalBlocker block(cameras_);
    cameras_->clear();
    NodeId fallback{};
    for (const NodeId id : scene.depthFirst()) {
        const Node& node = scene.at(id);
        const auto* camera = node.get<Camera>();
        if (!camera) continue;
        cameras_->addItem(nodeDisplayName(scene, id), id.value);
        if (!fallback.valid() || (id == scene.settings.activeCamera)) fallback = id;
    }
    if (!camera_.valid() && fallback.valid()) {
        camera_ = fallback;
        ruler_->setCamera(camera_);
    }
    cameras_->setCurrentIndex(cameras_->findData(camera_.value));
    const CameraPath* p = path();
    constantSpeed_->setChecked(p && p->constantSpeed);
    constantSpeed_->setEnabled(p && !p->empty());
}

void TimelinePanel::refreshKeyEditor() {
    const CameraPath* p = path();
    const auto key = ruler_->selectedKey();
    const bool has = p && key && *key < p->keys.size();
    deleteKey_->setEnabled(has || tracks_->selectedKey());
    refreshing_ = true;
    for (QDoubleSpinBox* field : keyFields_) field->setEnabled(has);
    if (has) {
        const CameraKey& k = p->keys[*key];
        const double values[7] = {k.position.x, k.position.y, k.position.z, k.yfov * kDegrees, k.focusDistance, k.lensRadius, k.time};
        for (int i = 0; i < 7; ++i) keyFields_[i]->setValue(values[i]);
    }
    refreshing_ = false;
}

void TimelinePanel::editSelectedKey() {
    const CameraPath* p = path();
    const auto key = ruler_->selectedKey();
    if (refreshing_ || !p || !key || *key >= p->keys.size()) return;
    CameraKey k = p->keys[*key];
    k.position = {keyFields_[0]->value(), keyFields_[1]->value(), keyFields_[2]->value()};
    k.yfov = static_cast<float>(keyFields_[3]->value() / kDegrees);
    k.focusDistance = static_cast<float>(keyFields_[4]->value());
    k.lensRadius = static_cast<float>(keyFields_[5]->value());
    if (k == p->keys[*key]) return;
    document_.push(std::make_unique<EditCameraKey>(camera_, *key, k));
}

void TimelinePanel::addKey() {
    if (!camera_.valid() && cameraMaker_) setCamera(cameraMaker_());
    if (!camera_.valid() || !keySource_) return;
    const double t = document_.currentTime();
    const CameraPath* p = path();
    // A key at an existing key's time replaces that key's pose instead.
    for (std::size_t i = 0; p && i < p->keys.size(); ++i)
        if (p->keys[i].time == t) {
            CameraKey k = keySource_(t);
            k.time = t;
            document_.push(std::make_unique<EditCameraKey>(camera_, i, k));
            ruler_->setSelectedKey(i);
            return;
        }
    document_.push(std::make_unique<AddCameraKey>(camera_, keySource_(t)));
    p = path();
    for (std::size_t i = 0; p && i < p->keys.size(); ++i)
        if (p->keys[i].time == t) ruler_->setSelectedKey(i);
}

void TimelinePanel::deleteKey() {
    if (const std::optional<NodeKey> nodeKey = tracks_->selectedKey()) {
        tracks_->setSelectedKey(std::nullopt);
        deleteNodeKey(document_, *nodeKey);
        return;
    }
    const auto key = ruler_->selectedKey();
    const CameraPath* p = path();
    if (!p || !key || *key >= p->keys.size()) return;
    ruler_->setSelectedKey(std::nullopt);
    document_.push(std::make_unique<RemoveCameraKey>(camera_, *key));
}

void TimelinePanel::setPlaying(bool on) {
    if (on) timer_.start(std::max(1, int(std::lround(1000.0 / fps()))));
    else timer_.stop();
    QSignalBlocker block(play_);
    play_->setChecked(on);
}

void TimelinePanel::stepFrame() {
    // Frames are t0 + k / fps exactly (docs/CLI.md): step the frame number, not the clock.
    const double t0 = document_.scene().settings.timeline.start;
    const long long frame = std::llround((document_.currentTime() - t0) * fps()) + 1;
    double t = t0 + double(frame) / fps();
    const double end = ruler_->range().end;
    if (t > end + 1e-9) {
        if (!loop_->isChecked()) {
            setPlaying(false);
            return;
        }
        t = t0;
    }
    document_.setCurrentTime(t);
}

} // namespace glint::editor
