#pragma once
// Counts and lists that describe a scene at a glance (glint info, the editor's status bar).
#include "scene/core/scene.h"

#include <cstddef>
#include <string>
#include <vector>

namespace glint {

struct MeshSummary {
    std::string name;
    std::size_t triangles = 0;
    std::size_t instances = 0; // nodes that instance this mesh
};

struct NamedItem {
    std::string name;
    std::string kind;   // "sun"/"point"/"spot", "perspective"/"orthographic", shape kind, ...
};

struct CameraPathSummary {
    std::string node;
    std::size_t keys = 0;
    double start = 0.0, end = 0.0;
};

struct AnimationSummary {
    std::string name;
    std::size_t channels = 0;
    double start = 0.0, end = 0.0;
};

struct SceneSummary {
    std::size_t nodes = 0;
    std::vector<MeshSummary> meshes;
    std::size_t uniqueTriangles = 0;
    std::size_t instancedTriangles = 0; // every instance counted
    std::vector<NamedItem> shapes;
    std::vector<std::string> materials;
    std::size_t textures = 0, images = 0, samplers = 0;
    std::vector<NamedItem> lights;
    std::vector<NamedItem> cameras;
    std::vector<AnimationSummary> animations;
    std::vector<CameraPathSummary> cameraPaths;
};

SceneSummary summarize(const Scene& scene);

const char* toString(LightType type);
const char* toString(Projection projection);
const char* toString(ShapeKind kind);

} // namespace glint
