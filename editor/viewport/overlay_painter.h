#pragma once
// The viewport's 2D overlays, drawn with QPainter over the rendered image: the gizmo of the
// current node, camera-path curves with their keys, the lights' and cameras' icons, messages, the BVH heat map's legend and the
// render region's frame. Geometry is projected with the
// view camera, so overlays and the path-traced image line up.
#include "editor/viewport/gizmo_math.h"
#include "editor/viewport/node_icons.h"
#include "renderer/bvh/aabb.h"
#include "scene/core/ids.h"

#include <QCoreApplication>
#include <QRectF>
#include <QString>

#include <vector>

class QPainter;

namespace glint::editor {

class Document;
class RenderView;

class OverlayPainter {
    Q_DECLARE_TR_FUNCTIONS(OverlayPainter)
public:
    OverlayPainter(QPainter& painter, const RenderView& view, const Document& document)
        : painter_(painter), view_(view), document_(document) {}
    // Every camera's path (the one looked through is skipped: it would sit on the image centre).
    void drawCameraPaths(NodeId lookingThrough);
    // An icon at every light and camera (but the camera looked through), clickable within
    // kIconPickRadius: a lamp with rays (a sun with a line along its light), a camera body.
    void drawNodeIcons(const std::vector<NodeIcon>& icons, NodeId lookingThrough);
    void drawGizmo(const GizmoFrame& frame, GizmoMode mode, int activeAxis);
    // Text over the top of the image: why nothing is drawn (red), or a hint about what is drawn.
    enum class MessageKind { Error, Hint };
    void drawMessage(const QString& text, MessageKind kind = MessageKind::Error);
    // The top-level BVH's leaves: one world box per instance.
    void drawBoxes(const std::vector<bvh::Aabb>& boxes);
    // The BVH heat map's legend: a colour bar from 0 to `scale` (nodes + primitives per camera ray).
    void drawCostLegend(float scale);
    // The render region: a dashed frame around `rect` (widget coordinates).
    void drawRegion(const QRectF& rect);

private:
    QPainter& painter_;
    const RenderView& view_;
    const Document& document_;
};

} // namespace glint::editor
