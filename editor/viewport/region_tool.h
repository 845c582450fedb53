#pragma once
// The viewport's render region (Ctrl+B, like Blender; Ctrl+Alt+B clears): arm it, drag a
// rectangle with the left button, and the path tracer spends its samples inside it only. The
// region is view state, never part of the document (it does not dirty the file), and is kept as
// fractions of the view, so it follows a resize proportionally.
#include "renderer/render_region.h"

#include <QPointF>
#include <QRectF>
#include <QSizeF>

#include <optional>

namespace glint::editor {

class RegionTool {
public:
    void arm() { armed_ = true; }    // the next left-button drag draws the region
    bool armed() const { return armed_; }
    bool dragging() const { return dragging_; }
    // Mouse events in widget coordinates; each returns true when it took the event.
    bool press(QPointF at);
    bool move(QPointF at);
    bool release(QPointF at, QSizeF view); // a drag under kMinimumPixels on a side is cancelled
    void cancel() { armed_ = dragging_ = false; }

    // Fractions of the view, from the top-left corner; nullopt: no region (the whole view).
    const std::optional<QRectF>& region() const { return region_; }
    void setRegion(const std::optional<QRectF>& fractions);
    renderer::RenderRegion renderRegion() const;
    // What the overlay frames, in widget coordinates: the drag in progress, else the region.
    std::optional<QRectF> frame(QSizeF view) const;

    static constexpr double kMinimumPixels = 3.0;

private:
    std::optional<QRectF> region_;
    bool armed_ = false;
    bool dragging_ = false;
    QPointF start_, end_;
};

} // namespace glint::editor
