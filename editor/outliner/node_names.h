#pragma once
// The name the editor shows for a node. Many glTF files name no nodes (2CylinderEngine's 82 have
// none): a blank row, an empty "Selected:" and a useless filter. A node without a name of its own
// is shown under one derived from what it holds (its mesh's name, "Camera 3", "Point light 7",
// "Sphere 2") or else "Node 12" (its id); the derived name is never written into the file.
#include "scene/core/scene.h"

#include <QString>

namespace glint::editor {

// The node's own name, else the derived one; empty only for a node the scene does not hold.
QString nodeDisplayName(const Scene& scene, NodeId id);
// Whether the node's name is its own (false: nodeDisplayName derived it).
bool hasOwnName(const Scene& scene, NodeId id);

} // namespace glint::editor
