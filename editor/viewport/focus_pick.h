#pragma once
// Pick focus: a click in the viewport sets the focus distance of the scene camera the view looks
// through to the distance of the surface under the cursor, measured along the camera's view axis
// (depth of field focuses on a plane, so a point off-centre is as far as its depth, not its ray).
#include "scene/core/ids.h"

#include <glm/glm.hpp>

#include <QPointF>
#include <QString>

#include <optional>

namespace glint::editor {

class Document;
class RenderView;

// Depth of `point` in front of a camera at `position` looking along unit `forward`; nullopt when
// it is not in front of it.
std::optional<double> depthAlongView(const glm::dvec3& position, const glm::dvec3& forward, const glm::dvec3& point);

// Picks at `at` (widget coordinates of `view`) and sets the looked-through camera's focus distance
// as one undo step. Returns what happened, for the status bar.
QString pickFocus(Document& document, RenderView& view, QPointF at);

} // namespace glint::editor
