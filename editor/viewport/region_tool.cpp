#include "editor/viewport/region_tool.h"

#include <algorithm>

namespace glint::editor {

bool RegionTool::press(QPointF at) {
    if (!armed_) return false;
    dragging_ = true;
    start_ = end_ = at;
    return true;
}

bool RegionTool::move(QPointF at) {
    if (!dragging_) return false;
    end_ = at;
    return true;
}

bool RegionTool::release(QPointF at, QSizeF view) {
    if (!dragging_) return false;
    end_ = at;
    armed_ = dragging_ = false;
    const QRectF drawn = QRectF(start_, end_).normalized().intersected(QRectF(QPointF(0, 0), view));
    if (drawn.width() < kMinimumPixels || drawn.height() < kMinimumPixels || view.isEmpty()) return true;
    setRegion(QRectF(drawn.x() / view.width(), drawn.y() / view.height(), drawn.width() / view.width(),
                     drawn.height() / view.height()));
    return true;
}

void RegionTool::setRegion(const std::optional<QRectF>& fractions) {
    if (!fractions) {
        region_.reset();
        return;
    }
    const QRectF r = fractions->normalized().intersected(QRectF(0, 0, 1, 1));
    if (r.isEmpty()) region_.reset();
    else region_ = r;
}

renderer::RenderRegion RegionTool::renderRegion() const {
    if (!region_) return {};
    return {true, float(region_->x()), float(region_->y()), float(region_->width()), float(region_->height())};
}

std::optional<QRectF> RegionTool::frame(QSizeF view) const {
    if (dragging_) return QRectF(start_, end_).normalized();
    if (!region_) return std::nullopt;
    return QRectF(region_->x() * view.width(), region_->y() * view.height(), region_->width() * view.width(),
                  region_->height() * view.height());
}

} // namespace glint::editor
