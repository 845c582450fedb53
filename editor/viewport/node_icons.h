#pragma once
// Lights and cameras have no surface to click (bar a sphere lamp's), so the viewport draws an icon
// at each and picks them in screen space: a click within kIconPickRadius of an icon's centre
// selects its node, the nearest icon to the cursor winning (then the nearer to the eye).
#include "scene/core/scene.h"

#include <glm/glm.hpp>

#include <optional>
#include <vector>

namespace glint::editor {

// Device-independent pixels: a little larger than the drawn icons (OverlayPainter::drawNodeIcons).
constexpr double kIconPickRadius = 8.0;

struct NodeIcon {
    NodeId node{};
    bool camera = false;        // else a light
    LightType light = LightType::Point;
    glm::dvec3 position{0.0};   // world
    glm::dvec3 forward{0.0, 0.0, -1.0}; // world: where a camera looks, a spot or sun shines
};

// The visible lights and cameras of a posed scene, in depth-first order.
std::vector<NodeIcon> nodeIcons(const Scene& posed);

struct ProjectedIcon {
    NodeId node{};
    glm::dvec2 pixel{0.0}; // widget coordinates
    double depth = 0.0;    // along the view, > 0 in front of the eye
};

struct ViewCamera;
// The icons seen through `camera` in a width x height view (widget pixels); `skip`: the camera
// looked through, whose icon would sit on the eye.
std::vector<ProjectedIcon> projectIcons(const std::vector<NodeIcon>& icons, const ViewCamera& camera, int width, int height, NodeId skip);

// The icon whose centre is within `radius` of `cursor`: the nearest to the cursor, ties to the
// smaller depth; none when no icon is that close.
std::optional<NodeId> nearestIcon(const std::vector<ProjectedIcon>& icons, glm::dvec2 cursor, double radius);

} // namespace glint::editor
