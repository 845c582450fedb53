#include "editor/viewport/focus_pick.h"

#include "editor/document/document.h"
#include "editor/properties/property_edits.h"
#include "editor/viewport/render_view.h"
#include "editor/viewport/scene_picker.h"

#include <QCoreApplication>

namespace glint::editor {
namespace {

struct FocusPick { // the translation context of the messages below
    Q_DECLARE_TR_FUNCTIONS(FocusPick)
};

} // namespace

std::optional<double> depthAlongView(const glm::dvec3& position, const glm::dvec3& forward, const glm::dvec3& point) {
    const double depth = glm::dot(point - position, forward);
    if (!(depth > 0.0)) return std::nullopt;
    return depth;
}

QString pickFocus(Document& document, RenderView& view, QPointF at) {
    const NodeId camera = view.lookThrough();
    const Node* node = document.scene().node(camera);
    if (!node || !node->get<Camera>())
        return FocusPick::tr("Pick focus works through a scene camera: select one and look through it (0) first.");
    // A camera path's keys carry their own focus (sampled over time): a static value would not show.
    if (!node->get<Camera>()->path.empty())
        return FocusPick::tr("Pick focus: %1 follows its camera path, whose keys set the focus; edit them in the timeline.")
            .arg(QString::fromStdString(node->name));
    const PickResult hit = view.picker().pick(view.rayAt(at));
    if (!hit.node.valid()) return FocusPick::tr("Pick focus: nothing under the cursor, the focus distance is unchanged.");
    // The view is placed exactly at the camera while looking through it (RenderView::placeAtCamera).
    const auto depth = depthAlongView(view.camera().position(), view.camera().forward(), glm::dvec3(hit.position));
    if (!depth) return FocusPick::tr("Pick focus: the surface is behind the camera, the focus distance is unchanged.");
    const float distance = static_cast<float>(*depth);
    const QString cameraName = QString::fromStdString(node->name); // before the edit replaces the node's data
    const QString error = editComponent(
        document, camera, [distance](Component& c) { std::get<Camera>(c).focusDistance = distance; }, 0);
    if (!error.isEmpty()) return error;
    return FocusPick::tr("Focus distance of %1: %2 m (%3)")
        .arg(cameraName)
        .arg(double(distance), 0, 'f', 3)
        .arg(QString::fromStdString(document.scene().at(hit.node).name));
}

} // namespace glint::editor
