// GLINT_shape's `portal`: the glTF index of the quad a portal quad is paired with. Each node's link
// is read as an index into the id table, since its partner may come later in the reading order;
// once every node is in the scene the links are checked as pairs. A file carries pairs only (the
// writer saves nothing else), so a link that is not half of two quads naming each other is
// dropped, named: a one-sided link would render as an ordinary quad anyway (portal.h).
#include "gltf_read_json.h"
#include "gltf_read_nodes.h"

namespace glint {

namespace {

std::string nodeName(int index) { return "nodes[" + std::to_string(index) + "]"; }

int gltfIndexOf(const GltfReadContext& ctx, NodeId id)
{
    for (std::size_t i = 0; i < ctx.nodeIds.size(); ++i)
        if (ctx.nodeIds[i] == id) return static_cast<int>(i);
    return -1;
}

const Shape* shapeOf(const Scene& scene, NodeId id) { return scene.contains(id) ? scene.at(id).get<Shape>() : nullptr; }

// Why the link from `id` (a shape naming `partner`) is not half of a pair; empty when it is.
std::string pairProblem(const GltfReadContext& ctx, NodeId id, const Shape& shape)
{
    if (shape.kind != ShapeKind::Quad) return "is on a shape that is not a quad; only quads are portals";
    if (shape.portal == id) return "names the node itself";
    const std::string partner = nodeName(gltfIndexOf(ctx, shape.portal));
    const Shape* other = shapeOf(ctx.scene, shape.portal);
    if (!other || other->kind != ShapeKind::Quad) return "names " + partner + ", which is not a quad";
    if (!other->portal.valid()) return "names " + partner + ", which names no portal back: they are not a pair";
    if (other->portal != id) return "names " + partner + ", which names " + nodeName(gltfIndexOf(ctx, other->portal)) + ": they are not a pair";
    return {};
}

} // namespace

NodeId readPortalLink(GltfReadContext& ctx, const Json& ext, const std::string& where)
{
    const Json* value = JsonReader{ctx.file}.member(ext, "portal");
    if (!value) return {};
    const std::string at = where + ".portal";
    const std::size_t count = ctx.nodeIds.size();
    if (!value->is_number_unsigned()) {
        ctx.warn("invalid-portal", at + " must be a node index (a non-negative integer): the link is dropped");
        return {};
    }
    const std::uint64_t index = value->get<std::uint64_t>();
    if (index >= count) {
        ctx.warn("invalid-portal", at + " is " + std::to_string(index) + ", but the file has " + std::to_string(count) + " nodes: the link is dropped");
        return {};
    }
    const NodeId id = ctx.nodeIds[static_cast<std::size_t>(index)];
    if (!id.valid()) ctx.warn("invalid-portal", at + " names " + nodeName(static_cast<int>(index)) + ", which is not loaded (outside the default scene): the link is dropped");
    return id;
}

// Every problem is found on the links as read, then the bad links are dropped: a link dropped first
// never makes its partner's look one-sided.
void checkPortalPairs(GltfReadContext& ctx)
{
    std::vector<NodeId> dropped;
    for (std::size_t i = 0; i < ctx.nodeIds.size(); ++i) {
        const NodeId id = ctx.nodeIds[i];
        const Shape* shape = shapeOf(ctx.scene, id);
        if (!shape || !shape->portal.valid()) continue;
        const std::string problem = pairProblem(ctx, id, *shape);
        if (problem.empty()) continue;
        ctx.warn("invalid-portal", nodeName(static_cast<int>(i)) + ".extensions.GLINT_shape.portal " + problem + ": the link is dropped");
        dropped.push_back(id);
    }
    for (const NodeId id : dropped) {
        Shape shape = *shapeOf(ctx.scene, id);
        shape.portal = {};
        ctx.scene.setComponent(id, shape);
    }
}

} // namespace glint
