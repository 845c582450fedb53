#pragma once
// The renderer benchmark's scenes, built at run time so that the repository holds no large geometry:
// the Cornell box as stored, the Stanford bunny in the same room (the two blocks hidden), and
// 16 instances of the bunny in the room (1,111,216 triangles through the two-level BVH).
#include "scene/core/scene.h"

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace glint::bench {

struct BenchScene {
    std::string name;
    Scene scene;
    std::size_t triangles = 0; // over visible mesh instances (an instance counts its mesh again)
};

// Vertices and triangular faces of a Wavefront OBJ (v and f lines; polygons fanned). Throws
// std::runtime_error naming the file when it cannot be read or holds no triangle.
Mesh loadObjMesh(const std::filesystem::path& file, MaterialId material);

// `room` is the Cornell box: its blocks are hidden and `copies` bunnies (1, or a square number)
// stand on the floor in a grid, in the floor's material.
Scene bunnyRoom(Scene room, Mesh bunny, int copies);

std::size_t visibleTriangles(const Scene& scene);

// Cornell box, bunny room, 16 bunnies.
std::vector<BenchScene> benchScenes(const Scene& cornellBox, const std::filesystem::path& bunnyObj);

} // namespace glint::bench
