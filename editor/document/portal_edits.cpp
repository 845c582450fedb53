#include "portal_edits.h"

#include "edit_operations.h"
#include "in_macro.h"
#include "node_placement.h"

#include "scene/history/asset_commands.h"
#include "scene/history/node_commands.h"
#include "scene/history/set_node_field.h"

#include <QCoreApplication>

namespace glint::editor {
namespace {

const Shape* quadOf(const Scene& scene, NodeId id) {
    const Node* node = scene.node(id);
    const Shape* shape = node ? node->get<Shape>() : nullptr;
    return shape && shape->kind == ShapeKind::Quad ? shape : nullptr;
}

// Sets one quad's link, as its own command inside the caller's macro.
void pushLink(Document& document, NodeId quad, NodeId partner) {
    Shape shape = *document.scene().at(quad).get<Shape>();
    if (shape.portal == partner) return;
    shape.portal = partner;
    document.push(std::make_unique<SetComponent>(quad, shape));
}

// Clears the link of `quad`'s present partner when that partner names `quad` back.
void unlinkPartnerOf(Document& document, NodeId quad) {
    const Shape* shape = quadOf(document.scene(), quad);
    if (!shape || !shape->portal.valid() || shape->portal == quad) return;
    const Shape* partner = quadOf(document.scene(), shape->portal);
    if (partner && partner->portal == quad) pushLink(document, shape->portal, {});
}

// A quad standing at `pose` (world) under `parent`, with its own material, linked to `partner`.
NodeId pushPortalQuad(Document& document, const QString& name, const Transform& pose, float edge, NodeId parent, NodeId partner) {
    const Scene& scene = document.scene();
    auto material = std::make_unique<AddAsset<Material>>(newShapeMaterial(scene));
    AddAsset<Material>* addedMaterial = material.get();
    document.push(std::move(material));
    Shape quad = std::get<Shape>(defaultShape(ShapeKind::Quad));
    quad.size = {edge, 1.0f, edge};
    quad.material = addedMaterial->id();
    quad.portal = partner;
    Node node;
    node.name = name.toStdString();
    node.local = parent.valid() ? fromMatrix(glm::inverse(scene.worldFromNode(parent)) * toMatrix(pose)) : pose;
    node.component = quad;
    auto command = std::make_unique<AddNode>(std::move(node), parent);
    AddNode* added = command.get();
    document.push(std::move(command));
    return added->nodeId();
}

} // namespace

QString addPortalPair(Document& document) {
    const Node* current = document.scene().node(document.currentNode());
    const NodeId parent = current ? current->parent : NodeId{};
    const PortalPairPlacement place = placePortalPair(document.viewFocus());
    NodeId a, b;
    const QString error = inMacro(document, QCoreApplication::translate("glint::editor::PortalEdits", "Add Portal Pair"), [&] {
        a = pushPortalQuad(document, QCoreApplication::translate("glint::editor::PortalEdits", "Portal A"), place.a, place.edge, parent, {});
        b = pushPortalQuad(document, QCoreApplication::translate("glint::editor::PortalEdits", "Portal B"), place.b, place.edge, parent, a);
        pushLink(document, a, b); // A's id was not known before it was added
    });
    if (error.isEmpty()) document.setSelection({a, b});
    return error;
}

QString linkPortal(Document& document, NodeId quad, NodeId partner) {
    const Scene& scene = document.scene();
    const Shape* shape = quadOf(scene, quad);
    if (!shape) return QCoreApplication::translate("glint::editor::PortalEdits", "Only a quad can be a portal.");
    if (partner == quad) return QCoreApplication::translate("glint::editor::PortalEdits", "A portal cannot lead to itself.");
    if (partner.valid() && !quadOf(scene, partner))
        return QCoreApplication::translate("glint::editor::PortalEdits", "A portal can only lead to another quad.");
    const bool paired = partner.valid() ? shape->portal == partner && quadOf(scene, partner)->portal == quad : !shape->portal.valid();
    if (paired) return {};
    const QString label = partner.valid() ? QCoreApplication::translate("glint::editor::PortalEdits", "Link Portals")
                                          : QCoreApplication::translate("glint::editor::PortalEdits", "Unlink Portal");
    return inMacro(document, label, [&] {
        unlinkPartnerOf(document, quad);
        if (partner.valid()) {
            unlinkPartnerOf(document, partner);
            pushLink(document, partner, quad);
        }
        pushLink(document, quad, partner);
    });
}

void relinkCopiedPortals(Document& document, const std::map<NodeId, NodeId>& copyOf) {
    for (const auto& [original, copy] : copyOf) {
        const Node* node = document.scene().node(copy);
        const Shape* shape = node ? node->get<Shape>() : nullptr;
        if (!shape || !shape->portal.valid()) continue;
        const auto partner = copyOf.find(shape->portal);
        pushLink(document, copy, partner == copyOf.end() ? NodeId{} : partner->second);
    }
}

std::vector<NodeId> portalCandidates(const Scene& scene, NodeId quad) {
    std::vector<NodeId> out;
    for (const NodeId id : scene.depthFirst())
        if (id != quad && quadOf(scene, id)) out.push_back(id);
    return out;
}

PortalLink portalLink(const Scene& scene, NodeId quad) {
    const Shape* shape = quadOf(scene, quad);
    if (!shape || !shape->portal.valid()) return PortalLink::None;
    const Shape* partner = shape->portal == quad ? nullptr : quadOf(scene, shape->portal);
    return partner && partner->portal == quad ? PortalLink::Paired : PortalLink::OneSided;
}

} // namespace glint::editor
