#include "editor/viewport/node_icons.h"

#include "editor/viewport/view_camera.h"
#include "renderer/gpu_scene/visibility.h"

namespace glint::editor {

std::vector<NodeIcon> nodeIcons(const Scene& posed) {
    std::vector<NodeIcon> icons;
    for (const NodeId id : posed.depthFirst()) {
        const Node& node = posed.at(id);
        const auto* light = node.get<Light>();
        if ((!light && !node.get<Camera>()) || !renderer::visibleInWorld(posed, node)) continue;
        const glm::dmat4 world(posed.worldFromNode(id));
        NodeIcon icon;
        icon.node = id;
        icon.camera = light == nullptr;
        if (light) icon.light = light->type;
        icon.position = glm::dvec3(world[3]);
        const glm::dvec3 forward(world * glm::dvec4(0.0, 0.0, -1.0, 0.0)); // glTF lights and cameras look along -Z
        if (glm::length(forward) > 0.0) icon.forward = glm::normalize(forward);
        icons.push_back(icon);
    }
    return icons;
}

std::vector<ProjectedIcon> projectIcons(const std::vector<NodeIcon>& icons, const ViewCamera& camera, int width, int height, NodeId skip) {
    std::vector<ProjectedIcon> out;
    for (const NodeIcon& icon : icons) {
        if (icon.node == skip) continue;
        const glm::dvec3 p = projectToPixels(camera, icon.position, width, height);
        if (p.z > 0.0) out.push_back({icon.node, {p.x, p.y}, p.z});
    }
    return out;
}

std::optional<NodeId> nearestIcon(const std::vector<ProjectedIcon>& icons, glm::dvec2 cursor, double radius) {
    const ProjectedIcon* best = nullptr;
    double bestDistance = radius;
    for (const ProjectedIcon& icon : icons) {
        if (!(icon.depth > 0.0)) continue;
        const double distance = glm::length(icon.pixel - cursor);
        if (distance > radius) continue;
        if (!best || distance < bestDistance || (distance == bestDistance && icon.depth < best->depth)) {
            best = &icon;
            bestDistance = distance;
        }
    }
    if (!best) return std::nullopt;
    return best->node;
}

} // namespace glint::editor
