#include "editor/timeline/time_ruler.h"

#include "editor/document/document.h"
#include "scene/history/camera_path_commands.h"

#include <QMouseEvent>
#include <QPainter>
#include <QPolygonF>

#include <cmath>

namespace glint::editor {

namespace {

constexpr double kMargin = 10.0;    // pixels left and right of the range
constexpr double kKeyHalfWidth = 5.0;

const CameraPath* pathOf(const Scene& scene, NodeId camera) {
    if (!camera.valid() || !scene.contains(camera)) return nullptr;
    const auto* c = scene.at(camera).get<Camera>();
    return c ? &c->path : nullptr;
}

} // namespace

TimeRuler::TimeRuler(Document& document, QWidget* parent) : QWidget(parent), document_(document) {
    setAccessibleName(tr("Time ruler"));
    setMinimumHeight(40);
    setFocusPolicy(Qt::ClickFocus);
    connect(&document_, &Document::timeChanged, this, qOverload<>(&QWidget::update));
    connect(&document_, &Document::changed, this, [this] {
        const CameraPath* path = pathOf(document_.scene(), camera_);
        if (selectedKey_ && (!path || *selectedKey_ >= path->keys.size())) setSelectedKey(std::nullopt);
        update();
    });
}

void TimeRuler::setCamera(NodeId camera) {
    camera_ = camera;
    setSelectedKey(std::nullopt);
    update();
}

void TimeRuler::setSelectedKey(std::optional<std::size_t> key) {
    if (key == selectedKey_) return;
    selectedKey_ = key;
    emit keySelected(key);
    update();
}

double TimeRuler::fps() const {
    const Timeline& t = document_.scene().settings.timeline;
    return t.fpsDenominator > 0 ? double(t.fpsNumerator) / t.fpsDenominator : 24.0;
}

TimeRange TimeRuler::range() const {
    const Timeline& t = document_.scene().settings.timeline;
    TimeRange r{t.start, t.end > t.start ? t.end : t.start + 5.0};
    if (t.end <= t.start)
        if (const CameraPath* path = pathOf(document_.scene(), camera_); path && !path->empty())
            r.end = std::max(r.end, path->keys.back().time + 1.0);
    r.end = std::max(r.end, document_.currentTime());
    return r;
}

double TimeRuler::xAt(double time) const { return xAtTime(range(), time, kMargin, width() - 2 * kMargin); }
double TimeRuler::timeAt(double x) const { return timeAtX(range(), x, kMargin, width() - 2 * kMargin); }

std::optional<std::size_t> TimeRuler::keyAt(double x) const {
    const CameraPath* path = pathOf(document_.scene(), camera_);
    if (!path) return std::nullopt;
    for (std::size_t i = 0; i < path->keys.size(); ++i)
        if (std::abs(xAt(path->keys[i].time) - x) <= kKeyHalfWidth + 1.0) return i;
    return std::nullopt;
}

void TimeRuler::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    p.fillRect(rect(), palette().base());
    const TimeRange r = range();
    // Second ticks with labels, frame ticks when they are far enough apart.
    p.setPen(palette().text().color());
    const double pixelsPerSecond = (width() - 2 * kMargin) / r.span();
    const double frameStep = 1.0 / fps();
    if (pixelsPerSecond * frameStep >= 4.0)
        for (double t = r.start; t <= r.end + 1e-9; t += frameStep) p.drawLine(QPointF(xAt(t), 0), QPointF(xAt(t), 4));
    for (double s = std::ceil(r.start); s <= r.end + 1e-9; s += 1.0) {
        p.drawLine(QPointF(xAt(s), 0), QPointF(xAt(s), 10));
        p.drawText(QPointF(xAt(s) + 2, 20), QString::number(s, 'g', 6));
    }
    // Keys.
    if (const CameraPath* path = pathOf(document_.scene(), camera_)) {
        const double y = height() - 14.0;
        for (std::size_t i = 0; i < path->keys.size(); ++i) {
            const double x = xAt(path->keys[i].time);
            QPolygonF diamond({{x, y - kKeyHalfWidth}, {x + kKeyHalfWidth, y}, {x, y + kKeyHalfWidth}, {x - kKeyHalfWidth, y}});
            p.setBrush(selectedKey_ == i ? QColor(255, 170, 40) : QColor(200, 200, 200));
            p.drawPolygon(diamond);
        }
    }
    // Playhead.
    p.setPen(QPen(QColor(230, 60, 60), 2));
    const double x = xAt(document_.currentTime());
    p.drawLine(QPointF(x, 0), QPointF(x, height()));
}

void TimeRuler::scrubTo(double x) {
    const TimeRange r = range();
    const double t = std::clamp(snapToFrame(timeAt(x), document_.scene().settings.timeline.start, fps()), r.start, r.end);
    document_.setCurrentTime(t);
}

void TimeRuler::mousePressEvent(QMouseEvent* event) {
    if (event->button() != Qt::LeftButton) return;
    if (const auto key = keyAt(event->position().x())) {
        setSelectedKey(key);
        draggedKey_ = key;
        dragInteraction_ = document_.beginInteraction();
        return;
    }
    scrubbing_ = true;
    scrubTo(event->position().x());
}

void TimeRuler::mouseMoveEvent(QMouseEvent* event) {
    if (scrubbing_) {
        scrubTo(event->position().x());
        return;
    }
    if (!draggedKey_) return;
    const CameraPath* path = pathOf(document_.scene(), camera_);
    if (!path || *draggedKey_ >= path->keys.size()) return;
    const double t = std::max(range().start, snapToFrame(timeAt(event->position().x()), document_.scene().settings.timeline.start, fps()));
    if (t == path->keys[*draggedKey_].time) return;
    // A key may not land on another key's time; MoveCameraKey refuses that, and the drag waits.
    for (const CameraKey& k : path->keys)
        if (k.time == t) return;
    auto command = std::make_unique<MoveCameraKey>(camera_, *draggedKey_, t);
    command->interaction = dragInteraction_;
    document_.push(std::move(command));
    // Follow the key if it passed a neighbour.
    path = pathOf(document_.scene(), camera_);
    for (std::size_t i = 0; path && i < path->keys.size(); ++i)
        if (path->keys[i].time == t) {
            draggedKey_ = i;
            selectedKey_ = i;
        }
    emit keySelected(selectedKey_);
}

void TimeRuler::mouseReleaseEvent(QMouseEvent*) {
    scrubbing_ = false;
    draggedKey_.reset();
}

} // namespace glint::editor
