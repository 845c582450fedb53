#pragma once
// Paired portals: two quads (Shape::portal) that name each other. What enters one quad, from
// either side, leaves the other: rays in the path tracer and the editor's camera alike.
//
// The map between the two is fixed by the quads' node frames. A point p in the entry quad's local
// space is the point turn * p in the exit quad's space, where turn is half a turn about local Z:
// local Y (the quad's normal) and X change sign, Z keeps its direction. So a ray that enters a
// quad's front face against its normal leaves the other quad's front face along its normal, and
// an image seen through a portal is never mirrored. A scale between the frames scales what is
// seen; quads of different sizes clip what passes to the entry quad's rectangle.
#include "scene/core/scene.h"

#include <glm/glm.hpp>

#include <optional>

namespace glint {

// Half a turn about local Z: localExit = portalTurn() * localEntry.
glm::mat4 portalTurn();

// The partner of `id` when `id` is a linked portal: a visible quad whose `portal` names a visible
// quad that names it back. A one-sided or dangling link is none: that quad is an ordinary surface.
std::optional<NodeId> portalPartner(const Scene& scene, NodeId id);

// Where a world-space point or direction that enters `entry` continues: worldFromNode(exit) *
// turn * nodeFromWorld(entry).
glm::mat4 portalWorldFromWorld(const Scene& scene, NodeId entry, NodeId exit);

struct PortalCrossing {
    NodeId entry;
    NodeId exit;
    float t = 0.0f;              // along the segment, 0..1
    glm::mat4 worldFromWorld{1}; // portalWorldFromWorld(entry, exit)
};

// The first linked portal whose rectangle the segment `from` -> `to` passes through, either side;
// none when it passes through none. For the editor's camera flying through.
std::optional<PortalCrossing> firstPortalCrossing(const Scene& scene, const glm::vec3& from, const glm::vec3& to);

} // namespace glint
