#include "scene/core/portal.h"

#include <cmath>

namespace glint {
namespace {

const Shape* portalQuad(const Scene& scene, NodeId id) {
    if (!scene.contains(id) || !scene.visibleInWorld(id)) return nullptr;
    const Shape* shape = scene.at(id).get<Shape>();
    return shape && shape->kind == ShapeKind::Quad && shape->portal.valid() ? shape : nullptr;
}

} // namespace

glm::mat4 portalTurn() {
    glm::mat4 turn(1.0f);
    turn[0][0] = -1.0f;
    turn[1][1] = -1.0f;
    return turn;
}

std::optional<NodeId> portalPartner(const Scene& scene, NodeId id) {
    const Shape* entry = portalQuad(scene, id);
    if (!entry || entry->portal == id) return std::nullopt;
    const Shape* exit = portalQuad(scene, entry->portal);
    if (!exit || exit->portal != id) return std::nullopt;
    return entry->portal;
}

glm::mat4 portalWorldFromWorld(const Scene& scene, NodeId entry, NodeId exit) {
    return scene.worldFromNode(exit) * portalTurn() * glm::inverse(scene.worldFromNode(entry));
}

std::optional<PortalCrossing> firstPortalCrossing(const Scene& scene, const glm::vec3& from, const glm::vec3& to) {
    std::optional<PortalCrossing> first;
    for (const NodeId id : scene.depthFirst()) {
        const auto partner = portalPartner(scene, id);
        if (!partner) continue;
        const glm::mat4 nodeFromWorld = glm::inverse(scene.worldFromNode(id));
        const glm::vec3 a(nodeFromWorld * glm::vec4(from, 1.0f));
        const glm::vec3 b(nodeFromWorld * glm::vec4(to, 1.0f));
        if ((a.y > 0.0f) == (b.y > 0.0f) || a.y == b.y) continue; // stays on one side of the plane
        const float t = a.y / (a.y - b.y);
        const glm::vec3 p = a + t * (b - a);
        const glm::vec3 size = scene.at(id).get<Shape>()->size;
        if (!(std::abs(p.x) <= 0.5f * size.x && std::abs(p.z) <= 0.5f * size.z)) continue;
        if (first && first->t <= t) continue;
        first = PortalCrossing{id, *partner, t, portalWorldFromWorld(scene, id, *partner)};
    }
    return first;
}

} // namespace glint
