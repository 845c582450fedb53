#pragma once
// Transform edits as an animator expects them. A node with keys shows its keys' pose at the current
// time, not its stored transform, so an edit starts from that pose and keys the node at the
// current time (otherwise the edit would not show); with auto key on (Document::autoKey) every
// edited node is keyed, a new track where it has none (Blender's and Maya's auto key).
#include "editor/document/document.h"

#include <QString>

#include <cstdint>

namespace glint::editor {

// The local transform `node` shows at the document's current time.
Transform shownTransform(const Document& document, NodeId node);

// Whether a transform edit of `node` keys it: it has keys, or auto key is on.
bool editKeysNode(const Document& document, NodeId node);

// Sets the node's transform to `local` and, where editKeysNode, keys it there at the current time:
// one undo step, merged with the previous one of the same drag (`interaction`). An error message,
// or empty.
QString pushTransform(Document& document, NodeId node, const Transform& local, std::uint64_t interaction);

// Keys `node` at t with `local` in its track's interpolation (linear for a new track): one command.
void pushNodeKey(Document& document, NodeId node, double t, const Transform& local, std::uint64_t interaction = 0);

} // namespace glint::editor
