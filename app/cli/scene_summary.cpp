#include "scene_summary.h"

#include "scene/anim/node_animation.h"

#include <algorithm>
#include <map>

namespace glint {

const char* toString(LightType type) {
    switch (type) {
    case LightType::Sun: return "sun";
    case LightType::Point: return "point";
    case LightType::Spot: return "spot";
    case LightType::Area: return "area";
    }
    return "unknown";
}

const char* toString(Projection projection) {
    return projection == Projection::Perspective ? "perspective" : "orthographic";
}

const char* toString(ShapeKind kind) {
    switch (kind) {
    case ShapeKind::Sphere: return "sphere";
    case ShapeKind::Quad: return "quad";
    case ShapeKind::Disk: return "disk";
    case ShapeKind::Box: return "box";
    case ShapeKind::Cylinder: return "cylinder";
    case ShapeKind::GroundPlane: return "groundPlane";
    }
    return "unknown";
}

namespace {

const char* lightKind(const Light& light) {
    if (light.type != LightType::Area) return toString(light.type);
    switch (light.areaShape) {
    case AreaShape::Rectangle: return "area rectangle";
    case AreaShape::Disk: return "area disk";
    case AreaShape::Sphere: return "area sphere";
    }
    return "area";
}

void summarizeNode(const Node& n, std::map<MeshId, std::size_t>& instances, SceneSummary& s) {
    if (auto* m = n.get<MeshInstance>()) ++instances[m->mesh];
    if (auto* shape = n.get<Shape>()) s.shapes.push_back({n.name, toString(shape->kind)});
    if (auto* light = n.get<Light>()) s.lights.push_back({n.name, lightKind(*light)});
    if (auto* cam = n.get<Camera>()) {
        s.cameras.push_back({n.name, toString(cam->projection)});
        if (!cam->path.empty())
            s.cameraPaths.push_back({n.name, cam->path.keys.size(), cam->path.keys.front().time, cam->path.keys.back().time});
    }
}

} // namespace

SceneSummary summarize(const Scene& scene) {
    SceneSummary s;
    s.nodes = scene.nodeCount();
    std::map<MeshId, std::size_t> instances;
    for (NodeId id : scene.depthFirst()) summarizeNode(scene.at(id), instances, s);
    for (const auto& [id, mesh] : scene.meshes) {
        std::size_t tris = mesh.triangleCount();
        std::size_t count = instances.count(id) ? instances.at(id) : 0;
        s.meshes.push_back({mesh.name, tris, count});
        s.uniqueTriangles += tris;
        s.instancedTriangles += tris * count;
    }
    for (const auto& [id, m] : scene.materials) s.materials.push_back(m.name);
    s.textures = scene.textures.size();
    s.images = scene.images.size();
    s.samplers = scene.samplers.size();
    for (const auto& [id, a] : scene.animations) {
        auto [start, end] = animationTimeSpan(a);
        s.animations.push_back({a.name, a.channels.size(), start, end});
    }
    return s;
}

} // namespace glint
