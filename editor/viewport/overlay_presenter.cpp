#include "editor/viewport/overlay_presenter.h"

#include "editor/document/document.h"
#include "editor/viewport/debug_image.h"
#include "editor/viewport/overlay_painter.h"
#include "editor/viewport/render_host.h"
#include "editor/viewport/render_view.h"
#include "editor/viewport/scene_picker.h"
#include "editor/viewport/view_picking.h"
#include "editor/viewport/view_tools.h"

#include <QPainter>

namespace glint::editor {

void OverlayPresenter::draw(RenderHost& host, const ViewTools& tools, ViewMode mode, NodeId lookThrough) {
    QPainter painter(&view_);
    const QImage& readBack = host.readBack();
    if (!readBack.isNull()) painter.drawImage(view_.rect(), readBack);
    if (comparing_ && !snapshot_.isNull()) drawComparison(painter);
    OverlayPainter overlays(painter, view_, document_);
    if (mode == ViewMode::BvhBoxes) overlays.drawBoxes(host.picker(mode).instanceBounds());
    if (mode == ViewMode::BvhCost && !readBack.isNull()) overlays.drawCostLegend(readBack.text(kCostScaleKey).toFloat());
    if (const auto frame = tools.region().frame(view_.size()); frame && !showsRaster(mode)) overlays.drawRegion(*frame);
    overlays.drawCameraPaths(lookThrough);
    overlays.drawNodeIcons(host.picking().icons(document_.scene(), document_.currentTime()), lookThrough);
    if (const NodeId node = document_.currentNode(); node.valid() && document_.scene().contains(node))
        overlays.drawGizmo(view_.gizmoFrame(node), tools.gizmoMode(), tools.activeGizmoAxis());
    const ViewportStats& stats = host.stats();
    if (!stats.error.isEmpty()) overlays.drawMessage(stats.error);
    else if (!stats.hint.isEmpty() && !showsRaster(mode)) overlays.drawMessage(stats.hint, OverlayPainter::MessageKind::Hint);
}

// The snapshot (A) on the left of a divider, the live view (B) on the right.
void OverlayPresenter::drawComparison(QPainter& painter) const {
    const int half = view_.width() / 2;
    painter.drawImage(QRect(0, 0, half, view_.height()), snapshot_, QRect(0, 0, snapshot_.width() / 2, snapshot_.height()));
    painter.setPen(QPen(Qt::white, 1));
    painter.drawLine(half, 0, half, view_.height());
    painter.drawText(QRect(4, 4, half - 8, 20), Qt::AlignLeft, RenderView::tr("A"));
    painter.drawText(QRect(half + 4, 4, half - 8, 20), Qt::AlignLeft, RenderView::tr("B"));
}

} // namespace glint::editor
