#pragma once
// Portal pairs in the editor (scene/core/portal.h): adding a linked pair, and linking a quad to
// another, each one undo step that leaves every link two-sided. Deleting one quad of a pair, or
// making it another kind, leaves its partner's link one-sided: that quad is an ordinary quad (the
// renderer and the camera ignore the link), the Properties panel says "not paired", undo restores
// the pair, and a save does not write the link (docs/FILE_FORMAT.md).
#include "document.h"

#include <QString>

#include <map>
#include <vector>

namespace glint::editor {

// Adds "Portal A" and "Portal B" (translated) linked to each other, at the view's focus, under
// the current node's parent, each with a material of its own; selects both.
QString addPortalPair(Document& document);

// Links `quad` and `partner` both ways (none: unlinks `quad`), first clearing the links to them of
// their previous partners, as one undo step. A no-op when they are already a pair.
QString linkPortal(Document& document, NodeId quad, NodeId partner);

// After copying nodes (Duplicate), inside the caller's macro: a copied quad's link follows its
// partner's copy when the partner was copied too, else it is cleared, so copying a pair makes a new
// pair and copying one side makes an ordinary quad. `copyOf`: original -> copy.
void relinkCopiedPortals(Document& document, const std::map<NodeId, NodeId>& copyOf);

// The quads `quad` may be linked to: every other quad node, in depth-first order.
std::vector<NodeId> portalCandidates(const Scene& scene, NodeId quad);

// What `quad`'s link is, for the Properties panel: none, a pair (hidden or not), or one-sided.
enum class PortalLink { None, Paired, OneSided };
PortalLink portalLink(const Scene& scene, NodeId quad);

} // namespace glint::editor
