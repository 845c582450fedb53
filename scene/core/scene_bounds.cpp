#include "scene/core/scene_bounds.h"

#include "scene/core/visibility.h"

#include <cmath>

namespace glint {
namespace {

bool finite(const glm::vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

Bounds meshBounds(const Mesh& mesh) {
    Bounds local;
    for (const Primitive& primitive : mesh.primitives)
        for (const glm::vec3& p : primitive.positions)
            if (finite(p)) local.grow(p);
    return local;
}

Bounds shapeBounds(const Shape& shape) {
    Bounds local;
    const auto box = [&](glm::vec3 half) { local.grow(-half), local.grow(half); };
    switch (shape.kind) {
    case ShapeKind::Sphere: box(glm::vec3(shape.radius)); break;
    case ShapeKind::Quad: box(0.5f * glm::vec3(shape.size.x, 0.0f, shape.size.z)); break;
    case ShapeKind::Disk: box({shape.radius, 0.0f, shape.radius}); break;
    case ShapeKind::Box: box(0.5f * shape.size); break;
    case ShapeKind::Cylinder: box({shape.radius, 0.5f * shape.height, shape.radius}); break;
    case ShapeKind::GroundPlane: break;
    }
    return local;
}

Bounds localBounds(const Scene& scene, const Node& node) {
    if (const auto* instance = node.get<MeshInstance>())
        if (const Mesh* mesh = scene.meshes.find(instance->mesh)) return meshBounds(*mesh);
    if (const auto* shape = node.get<Shape>()) return shapeBounds(*shape);
    return {};
}

void growByCorners(Bounds& world, const Bounds& local, const glm::mat4& worldFromLocal) {
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? local.max.x : local.min.x, (corner & 2) ? local.max.y : local.min.y,
                          (corner & 4) ? local.max.z : local.min.z);
        const glm::vec3 q(worldFromLocal * glm::vec4(p, 1.0f));
        if (finite(q)) world.grow(q);
    }
}

} // namespace

Bounds worldBounds(const Scene& scene) {
    Bounds world;
    for (const NodeId id : scene.depthFirst()) {
        const Node& node = *scene.node(id);
        if (!visibleInWorld(scene, node)) continue;
        const Bounds local = localBounds(scene, node);
        if (!local.empty()) growByCorners(world, local, scene.worldFromNode(id));
    }
    return world;
}

} // namespace glint
