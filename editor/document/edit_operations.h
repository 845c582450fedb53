#pragma once
// The edits the menus, the outliner and shortcuts share, each one undo step. Failures come back
// as a message (empty on success) rather than exceptions, for the status bar and the log.
#include "document.h"

#include "scene/core/components.h"

#include <QString>

namespace glint::editor {

// Deletes the selected nodes with their subtrees (a node inside a selected one goes with it).
QString deleteSelection(Document& document);
// Duplicates each selected subtree beside its original and selects the copies.
QString duplicateSelection(Document& document);
// Adds a node with `component` under the current node's parent (or as a root) and selects it.
QString addNode(Document& document, const QString& name, Component component);
// Renames one node (a no-op when the name is unchanged).
QString renameNode(Document& document, NodeId id, const QString& name);
// Moves nodes under `parent` (none: roots) at `index`, keeping where they are in the world.
QString reparentNodes(Document& document, const std::vector<NodeId>& nodes, NodeId parent, std::size_t index);
QString setVisible(Document& document, NodeId id, bool visible);

// A default component of each kind the "Add" menus offer.
Component defaultShape(ShapeKind kind);
Component defaultLight(LightType type);
Component defaultAreaLight(AreaShape shape);
Component defaultCamera();
// A new shape's own material, named uniquely in `scene`.
Material newShapeMaterial(const Scene& scene);

} // namespace glint::editor
