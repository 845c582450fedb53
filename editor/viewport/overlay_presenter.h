#pragma once
// What the viewport draws over its image, decided in one place: the G-buffer views' read-back
// image, the A/B comparison with a snapshot, the BVH boxes and heat-map legend, the render
// region's frame, camera paths, light and camera icons, the selected node's gizmo, and the notes
// (why nothing is drawn, why the image is black). OverlayPainter does the drawing itself.
#include "editor/viewport/view_modes.h"
#include "scene/core/ids.h"

#include <QImage>

namespace glint::editor {

class Document;
class RenderHost;
class RenderView;
class ViewTools;

class OverlayPresenter {
public:
    OverlayPresenter(RenderView& view, Document& document) : view_(view), document_(document) {}

    void takeSnapshot(QImage image) { snapshot_ = std::move(image); }
    bool hasSnapshot() const { return !snapshot_.isNull(); }
    void setComparing(bool on) { comparing_ = on; }

    // Paints over the widget after the host drew the image.
    void draw(RenderHost& host, const ViewTools& tools, ViewMode mode, NodeId lookThrough);

private:
    void drawComparison(QPainter& painter) const;

    RenderView& view_;
    Document& document_;
    QImage snapshot_;
    bool comparing_ = false;
};

} // namespace glint::editor
