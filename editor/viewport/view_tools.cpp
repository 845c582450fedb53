#include "editor/viewport/view_tools.h"

#include "editor/document/document.h"
#include "editor/viewport/gizmo_drag.h"
#include "editor/viewport/portal_travel.h"
#include "editor/viewport/render_view.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QWheelEvent>

#include <cmath>

namespace glint::editor {

namespace {

constexpr int kFlyIntervalMs = 16;
constexpr double kClickSlopPixels = 4.0;

} // namespace

ViewTools::ViewTools(RenderView& view, Document& document) : view_(view), document_(document) {
    flyTimer_.setInterval(kFlyIntervalMs);
    connect(&flyTimer_, &QTimer::timeout, this, &ViewTools::flyStep);
}

ViewTools::~ViewTools() = default;

bool ViewTools::navigating() const {
    return tool_ == Tool::Orbit || tool_ == Tool::Pan || tool_ == Tool::Zoom || tool_ == Tool::Fly || tool_ == Tool::Gizmo;
}

int ViewTools::activeGizmoAxis() const { return gizmoDrag_ ? gizmoDrag_->axis() : -1; }

void ViewTools::enter(Tool tool) {
    const bool wasArmed = tool_ == Tool::RegionArmed || tool_ == Tool::RegionDrag || tool_ == Tool::FocusArmed;
    tool_ = tool;
    if (tool == Tool::RegionArmed || tool == Tool::FocusArmed) view_.setCursor(Qt::CrossCursor);
    else if (wasArmed && tool != Tool::RegionDrag) view_.unsetCursor();
    if (tool != Tool::Gizmo) gizmoDrag_.reset();
    if (tool != Tool::Fly) {
        flyTimer_.stop();
        flyKeys_.clear();
    }
}

void ViewTools::setGizmoMode(GizmoMode mode) {
    gizmoMode_ = mode;
    emit gizmoModeChanged(mode);
    view_.update();
}

void ViewTools::setGizmoSpace(GizmoSpace space) {
    gizmoSpace_ = space;
    emit gizmoSpaceChanged(space);
    view_.update();
}

void ViewTools::armRenderRegion() {
    region_.arm();
    enter(Tool::RegionArmed);
}

void ViewTools::setRenderRegion(const std::optional<QRectF>& fractions) {
    region_.cancel();
    region_.setRegion(fractions);
    if (tool_ == Tool::RegionArmed || tool_ == Tool::RegionDrag) enter(Tool::Idle);
    view_.update();
}

void ViewTools::armFocusPick(bool on) {
    if (on) enter(Tool::FocusArmed);
    else if (tool_ == Tool::FocusArmed) enter(Tool::Idle);
}

bool ViewTools::startGizmoDrag(QPointF at) {
    const NodeId node = document_.currentNode();
    if (!node.valid() || !document_.scene().contains(node) || view_.lookThrough().valid()) return false;
    auto drag = std::make_unique<GizmoDrag>(document_, node, view_.gizmoFrame(node), gizmoMode_, view_.rayAt(at));
    if (!drag->active()) return false;
    enter(Tool::Gizmo);
    gizmoDrag_ = std::move(drag);
    return true;
}

void ViewTools::press(QMouseEvent* event) {
    const QPointF at = event->position();
    lastMouse_ = pressMouse_ = at;
    const Qt::MouseButton button = event->button();
    const auto mods = event->modifiers();
    if (button == Qt::LeftButton && tool_ == Tool::FocusArmed) {
        enter(Tool::Idle);
        emit focusClicked(at);
        return;
    }
    if (button == Qt::LeftButton && tool_ == Tool::RegionArmed) {
        region_.press(at);
        enter(Tool::RegionDrag);
        return;
    }
    if (button == Qt::LeftButton && !(mods & Qt::AltModifier)) {
        if (startGizmoDrag(at)) return;
        enter(Tool::Click);
        return;
    }
    if (button == Qt::LeftButton || (button == Qt::MiddleButton && !(mods & (Qt::ShiftModifier | Qt::ControlModifier)))) {
        enter(Tool::Orbit);
    } else if (button == Qt::MiddleButton) {
        enter((mods & Qt::ShiftModifier) ? Tool::Pan : Tool::Zoom);
    } else if (button == Qt::RightButton) {
        enter(Tool::Fly);
        flyTimer_.start();
    } else {
        return;
    }
    if (view_.lookThrough().valid()) view_.setLookThrough({}); // navigation leaves the scene camera
}

void ViewTools::move(QMouseEvent* event) {
    const QPointF at = event->position();
    if (tool_ == Tool::RegionDrag) {
        region_.move(at);
        view_.update();
        return;
    }
    const QPointF d = at - lastMouse_;
    lastMouse_ = at;
    ViewCamera& camera = view_.camera();
    const glm::dvec3 eye = camera.position();
    switch (tool_) {
    case Tool::Orbit: orbit(camera, d.x(), d.y()); break;
    case Tool::Pan: pan(camera, d.x(), d.y(), view_.height()); break;
    case Tool::Zoom: zoom(camera, -d.y() / 20.0); break;
    case Tool::Fly: look(camera, d.x(), d.y()); break;
    case Tool::Gizmo:
    {
        GizmoSnap snap = snap_; // Ctrl inverts snapping for this move
        snap.enabled = snap.enabled != bool(event->modifiers() & Qt::ControlModifier);
        gizmoDrag_->moveTo(view_.rayAt(at), snap);
        view_.noteMotion(false);
        return;
    }
    default: return;
    }
    finishCameraMove(eye);
}

void ViewTools::release(QMouseEvent* event) {
    const QPointF at = event->position();
    if (tool_ == Tool::RegionDrag) {
        region_.release(at, view_.size());
        enter(Tool::Idle);
        view_.update();
        return;
    }
    if (tool_ == Tool::RegionArmed || tool_ == Tool::FocusArmed) return; // still waiting for their click
    if (tool_ == Tool::Click) {
        const QPointF moved = at - pressMouse_;
        if (std::hypot(moved.x(), moved.y()) <= kClickSlopPixels) {
            if (inspecting_) emit inspected(at);
            else emit clicked(at, event->modifiers() & Qt::ShiftModifier);
        }
    }
    enter(Tool::Idle);
    view_.update();
}

void ViewTools::wheel(QWheelEvent* event) {
    if (view_.lookThrough().valid()) view_.setLookThrough({}); // as a drag does: zoom from the camera's view
    const glm::dvec3 eye = view_.camera().position();
    zoom(view_.camera(), event->angleDelta().y() / 120.0);
    finishCameraMove(eye);
}

bool ViewTools::keyPress(QKeyEvent* event) {
    if (tool_ == Tool::Fly) {
        if (!event->isAutoRepeat()) flyKeys_.insert(event->key());
        return true;
    }
    if (event->key() == Qt::Key_Escape) {
        switch (tool_) {
        case Tool::RegionArmed:
        case Tool::RegionDrag: setRenderRegion(region_.region()); return true; // drops the drag, keeps the region
        case Tool::FocusArmed: armFocusPick(false); return true;
        case Tool::Gizmo:
            gizmoDrag_->cancel();
            enter(Tool::Idle);
            view_.update();
            return true;
        default: break;
        }
    }
    switch (event->key()) {
    case Qt::Key_W: setGizmoMode(GizmoMode::Translate); return true;
    case Qt::Key_E: setGizmoMode(GizmoMode::Rotate); return true;
    case Qt::Key_R: setGizmoMode(GizmoMode::Scale); return true;
    default: return false;
    }
}

void ViewTools::keyRelease(QKeyEvent* event) {
    if (!event->isAutoRepeat()) flyKeys_.erase(event->key());
}

void ViewTools::focusOut() { flyKeys_.clear(); }

void ViewTools::flyStep() {
    glm::dvec3 move(0.0);
    const auto held = [&](int key) { return flyKeys_.count(key) != 0; };
    move.z += held(Qt::Key_W) - held(Qt::Key_S);
    move.x += held(Qt::Key_D) - held(Qt::Key_A);
    move.y += held(Qt::Key_E) - held(Qt::Key_Q);
    if (move == glm::dvec3(0.0)) return;
    // Speed follows the orbit distance: a metre is slow in a city and fast on a table.
    ViewCamera& camera = view_.camera();
    const double speed = std::max(0.1, camera.distance) * kFlyIntervalMs / 1000.0;
    const glm::dvec3 eye = camera.position();
    fly(camera, move * speed);
    finishCameraMove(eye);
}

// Every move of the view camera ends here, so none can pass through a portal without crossing it.
void ViewTools::finishCameraMove(const glm::dvec3& eyeBefore) {
    carryThroughPortal(view_.camera(), document_.scene(), eyeBefore);
    view_.noteMotion(true);
}

} // namespace glint::editor
