#include "editor/timeline/node_key_tracks.h"

#include "editor/document/document.h"
#include "editor/document/keyed_transform.h"
#include "editor/outliner/node_names.h"
#include "editor/timeline/time_ruler.h"
#include "scene/anim/node_keys.h"
#include "scene/anim/scene_at_time.h"
#include "scene/history/asset_commands.h"

#include <QCoreApplication>
#include <QMouseEvent>
#include <QPainter>
#include <QPolygonF>

#include <algorithm>
#include <cmath>

namespace glint::editor {

namespace {

constexpr double kKeyHalfWidth = 5.0;
constexpr double kSameTime = 1e-6; // node_keys.h's tolerance for "a key at t"

QString tr(const char* text) { return QCoreApplication::translate("glint::editor::NodeKeyTracks", text); }

double fpsOf(const Scene& scene) {
    const Timeline& t = scene.settings.timeline;
    return t.fpsDenominator > 0 && t.fpsNumerator > 0 ? double(t.fpsNumerator) / t.fpsDenominator : 24.0;
}

std::vector<double> keyTimes(const Scene& scene, NodeId node) {
    const std::optional<AnimationId> id = nodeKeyAnimation(scene, node);
    return id ? nodeKeyTimes(scene.animations.at(*id), node) : std::vector<double>{};
}

// Replaces the node's animation by `edited`, or removes it when no channel is left.
void pushAnimation(Document& document, AnimationId id, Animation edited, std::uint64_t interaction = 0) {
    CommandPtr command;
    if (edited.channels.empty()) command = std::make_unique<RemoveAsset<Animation>>(id);
    else command = std::make_unique<SetAsset<Animation>>(id, std::move(edited));
    command->interaction = interaction;
    document.push(std::move(command));
}

} // namespace

bool keyNodes(Document& document, const std::vector<NodeId>& nodes, double t) {
    std::vector<NodeId> keyed;
    for (const NodeId node : nodes)
        if (document.scene().contains(node)) keyed.push_back(node);
    if (keyed.empty()) return false;
    document.beginMacro(tr("Key transform"));
    for (const NodeId node : keyed) pushNodeKey(document, node, t, shownTransform(document, node));
    document.endMacro();
    return true;
}

bool deleteNodeKey(Document& document, const NodeKey& key) {
    const std::optional<AnimationId> id = nodeKeyAnimation(document.scene(), key.node);
    if (!id) return false;
    const Animation& animation = document.scene().animations.at(*id);
    Animation edited = withoutNodeKey(animation, key.node, key.time);
    if (edited == animation) return false;
    pushAnimation(document, *id, std::move(edited));
    return true;
}

bool moveNodeKey(Document& document, const NodeKey& key, double to, std::uint64_t interaction) {
    const std::optional<AnimationId> id = nodeKeyAnimation(document.scene(), key.node);
    if (!id || std::abs(key.time - to) <= kSameTime) return false;
    pushAnimation(document, *id, withNodeKeyMoved(document.scene().animations.at(*id), key.node, key.time, to), interaction);
    return true;
}

bool setNodeInterpolation(Document& document, NodeId node, int interpolation) {
    const std::optional<AnimationId> id = nodeKeyAnimation(document.scene(), node);
    if (!id) return false;
    const Animation& animation = document.scene().animations.at(*id);
    const auto wanted = static_cast<Interpolation>(interpolation);
    if (nodeKeyInterpolation(animation, node) == wanted) return false;
    pushAnimation(document, *id, withNodeInterpolation(animation, node, wanted));
    return true;
}

bool pasteNodeKey(Document& document, const NodeKey& copied, NodeId node, double t) {
    const Scene& scene = document.scene();
    if (!scene.contains(copied.node) || !scene.contains(node)) return false;
    const Transform local = sceneAt(scene, copied.time).at(copied.node).local;
    document.beginMacro(tr("Paste key"));
    pushNodeKey(document, node, t, local);
    document.endMacro();
    return true;
}

NodeKeyTracks::NodeKeyTracks(Document& document, const TimeRuler& ruler, QWidget* parent)
    : QWidget(parent), document_(document), ruler_(ruler) {
    setAccessibleName(tr("Node keys"));
    setFocusPolicy(Qt::ClickFocus);
    connect(&document_, &Document::changed, this, &NodeKeyTracks::refresh);
    connect(&document_, &Document::selectionChanged, this, &NodeKeyTracks::refresh);
    connect(&document_, &Document::timeChanged, this, qOverload<>(&QWidget::update));
}

std::vector<NodeId> NodeKeyTracks::rows() const {
    const Scene& scene = document_.scene();
    std::vector<NodeId> out;
    for (const NodeId id : scene.depthFirst())
        if (nodeKeyAnimation(scene, id)) out.push_back(id);
    const NodeId current = document_.currentNode();
    if (current.valid() && scene.contains(current) && std::find(out.begin(), out.end(), current) == out.end())
        out.push_back(current);
    return out;
}

QSize NodeKeyTracks::sizeHint() const { return {400, int(std::max<std::size_t>(1, rows().size())) * kRowHeight}; }

void NodeKeyTracks::setSelectedKey(std::optional<NodeKey> key) {
    if (key == selected_) return;
    selected_ = key;
    emit keySelected(key);
    update();
}

void NodeKeyTracks::refresh() {
    if (selected_) {
        const std::vector<double> times = keyTimes(document_.scene(), selected_->node);
        const bool stillThere = std::any_of(times.begin(), times.end(), [&](double t) { return std::abs(t - selected_->time) <= kSameTime; });
        if (!stillThere) setSelectedKey(std::nullopt);
    }
    updateGeometry();
    update();
}

std::optional<NodeKey> NodeKeyTracks::keyAt(QPointF at) const {
    const std::vector<NodeId> shown = rows();
    const auto row = static_cast<std::size_t>(std::max(0.0, at.y()) / kRowHeight);
    if (row >= shown.size()) return std::nullopt;
    for (const double t : keyTimes(document_.scene(), shown[row]))
        if (std::abs(ruler_.xAt(t) - at.x()) <= kKeyHalfWidth + 1.0) return NodeKey{shown[row], t};
    return std::nullopt;
}

void NodeKeyTracks::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    p.fillRect(rect(), palette().base());
    const Scene& scene = document_.scene();
    const std::vector<NodeId> shown = rows();
    const NodeId current = document_.currentNode();
    for (std::size_t row = 0; row < shown.size(); ++row) {
        const double y = rowCentreY(row);
        const QRectF band(0, y - 0.5 * kRowHeight, width(), kRowHeight);
        if (shown[row] == current) p.fillRect(band, palette().alternateBase());
        p.setPen(palette().placeholderText().color());
        p.drawText(band.adjusted(4, 0, -4, 0), Qt::AlignRight | Qt::AlignVCenter, nodeDisplayName(scene, shown[row]));
        p.setPen(palette().text().color());
        for (const double t : keyTimes(scene, shown[row])) {
            const double x = ruler_.xAt(t);
            const QPolygonF diamond({{x, y - kKeyHalfWidth}, {x + kKeyHalfWidth, y}, {x, y + kKeyHalfWidth}, {x - kKeyHalfWidth, y}});
            const bool selected = selected_ && selected_->node == shown[row] && std::abs(selected_->time - t) <= kSameTime;
            p.setBrush(selected ? QColor(255, 170, 40) : QColor(150, 190, 240));
            p.drawPolygon(diamond);
        }
    }
    p.setPen(QPen(QColor(230, 60, 60), 2));
    const double x = ruler_.xAt(document_.currentTime());
    p.drawLine(QPointF(x, 0), QPointF(x, height()));
}

void NodeKeyTracks::mousePressEvent(QMouseEvent* event) {
    if (event->button() != Qt::LeftButton) return;
    const std::optional<NodeKey> key = keyAt(event->position());
    setSelectedKey(key);
    if (!key) return;
    document_.setSelection({key->node});
    dragged_ = key;
    dragInteraction_ = document_.beginInteraction();
}

void NodeKeyTracks::mouseMoveEvent(QMouseEvent* event) {
    if (!dragged_) return;
    const Scene& scene = document_.scene();
    const double t = std::max(ruler_.range().start,
                              snapToFrame(ruler_.timeAt(event->position().x()), scene.settings.timeline.start, fpsOf(scene)));
    // A key may not land on another of the row's keys; the drag waits.
    for (const double other : keyTimes(scene, dragged_->node))
        if (std::abs(other - t) <= kSameTime) return;
    if (!moveNodeKey(document_, *dragged_, t, dragInteraction_)) return;
    dragged_->time = t;
    selected_ = dragged_;
    emit keySelected(selected_);
    update();
}

void NodeKeyTracks::mouseReleaseEvent(QMouseEvent*) { dragged_.reset(); }

} // namespace glint::editor
