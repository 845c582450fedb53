#pragma once
// The forms the properties panels stack, one function per section. Each form reads the document
// through getters and edits it through commands; `report` receives error messages.
#include "property_form.h"

#include "scene/core/ids.h"

#include <QString>

#include <cstddef>
#include <cstdint>
#include <functional>

class QAction;

namespace glint {
class Scene;
}

namespace glint::editor {

class Document;
using Report = std::function<void(const QString&)>;

// The viewport's own settings, which belong to the editor (preferences), not to the document: its
// sample cap (0 = none) and its pause. Empty functions: there is no viewport.
struct ViewportControls {
    std::function<int()> sampleCap;
    std::function<void(int)> setSampleCap;
    QAction* pause = nullptr;
    explicit operator bool() const { return sampleCap && setSampleCap; }
};

PropertyForm* makeNodeForm(Document& document, NodeId node, const Report& report, QWidget* parent);
PropertyForm* makeTransformForm(Document& document, NodeId node, const Report& report, QWidget* parent);
PropertyForm* makeShapeForm(Document& document, NodeId node, const Report& report, QWidget* parent);
// A quad's "Portal to" choice (portal_field.cpp); part of the shape form.
void addPortalField(PropertyForm* form, Document& document, NodeId quad, const Report& report);
PropertyForm* makeLightForm(Document& document, NodeId node, const Report& report, QWidget* parent);
PropertyForm* makeCameraForm(Document& document, NodeId node, const Report& report, QWidget* parent);
PropertyForm* makeMaterialForm(Document& document, MaterialId material, const Report& report, QWidget* parent);
// The node's material slots: a shape's one, or one per primitive of a mesh (each assignable, and
// `showPrimitive` picks the one whose material the material form below shows).
PropertyForm* makeMaterialSlotsForm(Document& document, NodeId node, std::size_t shownPrimitive,
                                    const std::function<void(std::size_t)>& showPrimitive, const Report& report, QWidget* parent);
// The material of a node's shape, or of primitive `primitive` of its mesh (clamped), or none.
MaterialId nodeMaterial(const Scene& scene, NodeId node, std::size_t primitive);
// Bit i set: texture slot i (material_operations.h textureSlots()) holds a texture.
std::uint32_t texturedSlots(const Scene& scene, MaterialId material);
PropertyForm* makeEnvironmentForm(Document& document, const Report& report, QWidget* parent);
PropertyForm* makeFogForm(Document& document, const Report& report, QWidget* parent);
PropertyForm* makeRenderForm(Document& document, const Report& report, QWidget* parent);
PropertyForm* makeProjectForm(Document& document, const Report& report, QWidget* parent);
PropertyForm* makeReconstructionForm(Document& document, const Report& report, QWidget* parent);
PropertyForm* makeViewportForm(Document& document, const ViewportControls& controls, QWidget* parent);

} // namespace glint::editor
