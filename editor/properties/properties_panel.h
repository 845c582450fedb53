#pragma once
// The properties dock for the current node: node, transform, its component and its material.
// The forms are rebuilt only when what they show changes kind (another node, another component
// or material); otherwise they re-read the document, so a slider being dragged survives the
// document's changed() signal its own edits cause.
#include "sections.h"

#include "scene/core/ids.h"
#include "scene/history/change_set.h"

#include <QScrollArea>

#include <cstddef>
#include <cstdint>
#include <vector>

class QVBoxLayout;

namespace glint::editor {

class Document;
class PropertyForm;

class PropertiesPanel : public QScrollArea {
    Q_OBJECT
public:
    // scene = true: the environment and render-settings panel instead of the node's.
    PropertiesPanel(Document& document, bool scene, QWidget* parent = nullptr);

    const std::vector<PropertyForm*>& forms() const { return forms_; }
    // The scene panel's Viewport section, first of its forms (the editor's, not the document's).
    void setViewportControls(ViewportControls controls);
    // Read every field again: for settings that change outside the document (preferences).
    void refresh() { update(); }

signals:
    void message(const QString& text);

protected:
    void changeEvent(QEvent* event) override;

private:
    struct Key {
        NodeId node;
        std::size_t component = 0;
        MaterialId material;
        int lightType = -1;
        int areaShape = -1;  // an area light's fields depend on its shape (a disk has a diameter)
        int shapeKind = -1;  // the fields shown depend on the kind (a sphere has no height)
        int projection = -1;
        std::size_t primitive = 0;      // which primitive's material a mesh shows
        std::uint32_t texturedSlots = 0; // slots with a texture show its sampler and transform
        bool operator==(const Key&) const = default;
    };
    Key currentKey() const;
    void update();
    void rebuild();

    Document& document_;
    bool scene_;
    QWidget* content_ = nullptr;
    QVBoxLayout* layout_ = nullptr;
    std::vector<PropertyForm*> forms_;
    Key shown_;
    std::size_t primitive_ = 0; // the primitive of the current mesh whose material is shown
    NodeId primitiveNode_;      // the node primitive_ belongs to
    bool built_ = false;
    ViewportControls viewportControls_;
};

} // namespace glint::editor
