#pragma once
// Small helpers the property panels share: copy a value out of the document, change it, push the
// matching command tagged with the drag's interaction serial. Errors become a message.
#include "editor/document/document.h"

#include "scene/core/settings.h"

#include <QString>

#include <functional>

namespace glint::editor {

QString editTransform(Document& document, NodeId node, const std::function<void(Transform&)>& change,
                      std::uint64_t interaction);
QString editComponent(Document& document, NodeId node, const std::function<void(Component&)>& change,
                      std::uint64_t interaction);
QString editMaterial(Document& document, MaterialId material, const std::function<void(Material&)>& change,
                     std::uint64_t interaction);
QString editSettings(Document& document, const std::function<void(ProjectSettings&)>& change,
                     std::uint64_t interaction);

// The material a node's shape or mesh uses (the first primitive's for meshes), or none.
MaterialId materialOf(const Scene& scene, NodeId node);

} // namespace glint::editor
