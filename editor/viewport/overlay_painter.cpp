#include "editor/viewport/overlay_painter.h"

#include "editor/document/document.h"
#include "editor/viewport/debug_image.h"
#include "editor/viewport/render_view.h"
#include "scene/anim/camera_path_sampling.h"

#include <QFontMetrics>
#include <QPainter>
#include <QPainterPath>

#include <cmath>
#include <numbers>

namespace glint::editor {

namespace {

constexpr int kCurveSamples = 96;
constexpr int kRingSegments = 48;

QColor axisColour(int axis, bool active) {
    static const QColor colours[3] = {QColor(230, 70, 70), QColor(90, 200, 80), QColor(70, 120, 240)};
    return active ? QColor(255, 220, 60) : colours[axis];
}

} // namespace

void OverlayPainter::drawCameraPaths(NodeId lookingThrough) {
    painter_.setRenderHint(QPainter::Antialiasing);
    for (const auto& [id, node] : document_.scene().nodes()) {
        const auto* camera = node.get<Camera>();
        if (!camera || camera->path.empty() || id == lookingThrough) continue;
        const CameraPath& path = camera->path;
        const double t0 = path.keys.front().time, t1 = path.keys.back().time;
        std::vector<double> times;
        for (int i = 0; i <= kCurveSamples; ++i) times.push_back(t0 + (t1 - t0) * i / kCurveSamples);
        QPainterPath curve;
        bool open = false;
        for (const CameraKey& k : sampleCameraPath(path, times)) {
            const auto p = view_.project(k.position);
            if (!p) { open = false; continue; }
            if (open) curve.lineTo(*p); else curve.moveTo(*p);
            open = true;
        }
        const bool selected = document_.isSelected(id);
        painter_.setPen(QPen(selected ? QColor(255, 170, 40) : QColor(200, 200, 200), selected ? 2.0 : 1.0));
        painter_.setBrush(Qt::NoBrush);
        painter_.drawPath(curve);
        painter_.setBrush(selected ? QColor(255, 170, 40) : QColor(230, 230, 230));
        for (const CameraKey& key : path.keys)
            if (const auto p = view_.project(key.position)) painter_.drawEllipse(*p, 4.0, 4.0);
        // The camera's position at the current time.
        if (const auto p = view_.project(sampleCameraPath(path, document_.currentTime()).position)) {
            painter_.setBrush(QColor(255, 80, 80));
            painter_.drawEllipse(*p, 5.0, 5.0);
        }
    }
}

void OverlayPainter::drawNodeIcons(const std::vector<NodeIcon>& icons, NodeId lookingThrough) {
    constexpr double kLampRadius = 4.0, kRayInner = 5.5, kRayOuter = 8.0; // within kIconPickRadius
    painter_.setRenderHint(QPainter::Antialiasing);
    for (const NodeIcon& icon : icons) {
        if (icon.node == lookingThrough) continue;
        const auto centre = view_.project(icon.position);
        if (!centre) continue;
        const bool selected = document_.isSelected(icon.node);
        const QColor ink = selected ? QColor(255, 170, 40) : QColor(235, 235, 235);
        painter_.setPen(QPen(QColor(0, 0, 0, 160), 3.0)); // a dark halo keeps icons readable on bright images
        painter_.setBrush(Qt::NoBrush);
        const QRectF body(*centre - QPointF(6.0, 4.0), QSizeF(12.0, 8.0));
        if (icon.camera) painter_.drawRect(body);
        else painter_.drawEllipse(*centre, kLampRadius, kLampRadius);
        painter_.setPen(QPen(ink, 1.5));
        if (icon.camera) {
            painter_.drawRect(body);
            // Which way it looks, as a short line towards where its -Z axis points on screen.
            if (const auto ahead = view_.project(icon.position + 0.25 * icon.forward)) {
                const QPointF d = *ahead - *centre;
                const double length = std::hypot(d.x(), d.y());
                if (length > 1e-6) painter_.drawLine(*centre, *centre + d * (kRayOuter + 4.0) / length);
            }
            continue;
        }
        painter_.setBrush(ink);
        painter_.drawEllipse(*centre, kLampRadius - 1.0, kLampRadius - 1.0);
        for (int i = 0; i < 8; ++i) {
            const double angle = std::numbers::pi * i / 4.0;
            const QPointF u(std::cos(angle), std::sin(angle));
            painter_.drawLine(*centre + kRayInner * u, *centre + kRayOuter * u);
        }
    }
}

void OverlayPainter::drawGizmo(const GizmoFrame& frame, GizmoMode mode, int activeAxis) {
    painter_.setRenderHint(QPainter::Antialiasing);
    const auto origin = view_.project(frame.origin);
    if (!origin) return;
    for (int a = 0; a < 3; ++a) {
        painter_.setPen(QPen(axisColour(a, a == activeAxis), 2.5));
        painter_.setBrush(axisColour(a, a == activeAxis));
        if (mode == GizmoMode::Rotate) {
            // A ring about the axis, in the plane of the other two.
            const glm::dvec3 u = frame.axes[(a + 1) % 3], v = frame.axes[(a + 2) % 3];
            QPainterPath ring;
            bool open = false;
            for (int i = 0; i <= kRingSegments; ++i) {
                const double angle = 2.0 * std::numbers::pi * i / kRingSegments;
                const auto p = view_.project(frame.origin + frame.size * (std::cos(angle) * u + std::sin(angle) * v));
                if (!p) { open = false; continue; }
                if (open) ring.lineTo(*p); else ring.moveTo(*p);
                open = true;
            }
            painter_.setBrush(Qt::NoBrush);
            painter_.drawPath(ring);
            continue;
        }
        const auto tip = view_.project(frame.origin + frame.size * frame.axes[a]);
        if (!tip) continue;
        painter_.drawLine(*origin, *tip);
        if (mode == GizmoMode::Scale) painter_.drawRect(QRectF(*tip - QPointF(4, 4), QSizeF(8, 8)));
        else painter_.drawEllipse(*tip, 4.0, 4.0);
    }
}

void OverlayPainter::drawBoxes(const std::vector<bvh::Aabb>& boxes) {
    painter_.setRenderHint(QPainter::Antialiasing);
    painter_.setPen(QPen(QColor(80, 220, 255), 1.0));
    for (const bvh::Aabb& box : boxes) {
        if (box.empty()) continue;
        const auto corner = [&](int c) {
            return glm::dvec3((c & 1) ? box.hi.x : box.lo.x, (c & 2) ? box.hi.y : box.lo.y, (c & 4) ? box.hi.z : box.lo.z);
        };
        for (int c = 0; c < 8; ++c)
            for (const int bit : {1, 2, 4}) {
                if (c & bit) continue;
                const auto a = view_.project(corner(c)), b = view_.project(corner(c | bit));
                if (a && b) painter_.drawLine(*a, *b);
            }
    }
}

void OverlayPainter::drawCostLegend(float scale) {
    constexpr int kBarWidth = 120, kBarHeight = 10, kMargin = 8, kSteps = 60;
    const QFontMetrics metrics = painter_.fontMetrics();
    const int textHeight = metrics.height();
    const QRect box(view_.width() - kBarWidth - 2 * kMargin, view_.height() - kBarHeight - 2 * textHeight - 2 * kMargin,
                    kBarWidth + kMargin, kBarHeight + 2 * textHeight + kMargin);
    painter_.setRenderHint(QPainter::Antialiasing, false);
    painter_.fillRect(box, QColor(0, 0, 0, 160));
    const QRect bar(box.left() + kMargin / 2, box.top() + textHeight + kMargin / 2, kBarWidth, kBarHeight);
    for (int i = 0; i < kSteps; ++i) {
        const int x0 = bar.left() + bar.width() * i / kSteps, x1 = bar.left() + bar.width() * (i + 1) / kSteps;
        painter_.fillRect(QRect(x0, bar.top(), x1 - x0, bar.height()), heatColour((float(i) + 0.5f) / float(kSteps)));
    }
    painter_.setPen(Qt::white);
    painter_.drawText(QRect(bar.left(), box.top() + 2, bar.width(), textHeight), Qt::AlignLeft | Qt::AlignVCenter,
                      tr("BVH nodes + primitives"));
    const QRect labels(bar.left(), bar.bottom() + 2, bar.width(), textHeight);
    painter_.drawText(labels, Qt::AlignLeft | Qt::AlignVCenter, QStringLiteral("0"));
    painter_.drawText(labels, Qt::AlignRight | Qt::AlignVCenter, QString::number(double(scale), 'g', 6));
}

void OverlayPainter::drawRegion(const QRectF& rect) {
    painter_.setRenderHint(QPainter::Antialiasing, false);
    painter_.setBrush(Qt::NoBrush);
    painter_.setPen(QPen(QColor(0, 0, 0, 200), 1.0));
    painter_.drawRect(rect);
    QPen dashed(QColor(255, 200, 40), 1.0, Qt::DashLine);
    painter_.setPen(dashed);
    painter_.drawRect(rect);
}

void OverlayPainter::drawMessage(const QString& text, MessageKind kind) {
    painter_.setPen(kind == MessageKind::Error ? QColor(255, 120, 120) : QColor(230, 230, 230));
    painter_.drawText(QRectF(8, 8, view_.width() - 16, view_.height() - 16), Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap, text);
}

} // namespace glint::editor
