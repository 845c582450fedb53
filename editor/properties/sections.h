#pragma once
// The forms the properties panels stack, one function per section. Each form reads the document
// through getters and edits it through commands; `report` receives error messages.
#include "property_form.h"

#include "scene/core/ids.h"

#include <QString>

#include <functional>

namespace glint::editor {

class Document;
using Report = std::function<void(const QString&)>;

PropertyForm* makeNodeForm(Document& document, NodeId node, const Report& report, QWidget* parent);
PropertyForm* makeTransformForm(Document& document, NodeId node, const Report& report, QWidget* parent);
PropertyForm* makeShapeForm(Document& document, NodeId node, const Report& report, QWidget* parent);
PropertyForm* makeLightForm(Document& document, NodeId node, const Report& report, QWidget* parent);
PropertyForm* makeCameraForm(Document& document, NodeId node, const Report& report, QWidget* parent);
PropertyForm* makeMaterialForm(Document& document, MaterialId material, const Report& report, QWidget* parent);
PropertyForm* makeEnvironmentForm(Document& document, const Report& report, QWidget* parent);
PropertyForm* makeRenderForm(Document& document, const Report& report, QWidget* parent);
PropertyForm* makeProjectForm(Document& document, const Report& report, QWidget* parent);
PropertyForm* makeReconstructionForm(Document& document, const Report& report, QWidget* parent);

} // namespace glint::editor
