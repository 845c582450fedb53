#pragma once
// Assimp's scene -> glint::Scene, in metres and +Y up, with metallic-roughness materials.
// Runs inside glint-import-worker; a plain function so that tests can call it in-process.
#include "scene/io/scene_io.h"

#include <cstdint>
#include <filesystem>

struct aiScene;

namespace glint {

struct ConvertOptions {
    std::filesystem::path sourceFile;  // names warnings; its folder resolves (and confines) textures
    std::uint64_t maxTriangles = 64'000'000;
    std::uint64_t maxTextureBytes = 256ull << 20; // per texture file
};

// Throws FileError ("no-geometry", "too-many-triangles"); drops what glTF-level Glint cannot keep
// (points and lines, skins, morph targets, Assimp animations, lights, cameras) with a warning each.
LoadResult convertAssimpScene(const aiScene& scene, const ConvertOptions& options);

} // namespace glint
