#pragma once
// Scenes written by the tests themselves (no test data to keep): a quad whose base colour texture
// file does not exist, seen by a camera under a grey sky, and a scene of many wavy grid meshes for
// preparation-time tests. Shared by the command-line and the editor tests.
#include "scene/core/scene.h"
#include "scene/io/scene_io.h"

#include <cmath>
#include <filesystem>
#include <string>

namespace glint::test {

inline constexpr const char* kMissingTextureFile = "missing_texture.png";

inline Primitive quadPrimitive(MaterialId material) {
    Primitive p;
    p.positions = {{-1.0f, -1.0f, 0.0f}, {1.0f, -1.0f, 0.0f}, {1.0f, 1.0f, 0.0f}, {-1.0f, 1.0f, 0.0f}};
    p.normals.assign(4, glm::vec3(0.0f, 0.0f, 1.0f));
    p.uv0 = {{0.0f, 1.0f}, {1.0f, 1.0f}, {1.0f, 0.0f}, {0.0f, 0.0f}};
    p.indices = {0, 1, 2, 0, 2, 3};
    p.material = material;
    return p;
}

inline NodeId addCamera(Scene& scene, float z) {
    Node camera;
    camera.name = "camera";
    camera.local.translation = {0.0f, 0.0f, z};
    camera.component = Camera{};
    return scene.addNode(std::move(camera));
}

// A textured quad 3 m in front of the camera; the texture's file is missing.
inline Scene missingTextureScene() {
    Scene scene;
    scene.settings.environment.color = glm::vec3(0.5f);
    Image image;
    image.uri = kMissingTextureFile;
    image.missing = true;
    const ImageId imageId = scene.images.add(std::move(image));
    Texture texture;
    texture.image = imageId;
    const TextureId textureId = scene.textures.add(std::move(texture));
    Material material;
    material.baseColorTexture.texture = textureId;
    const MaterialId materialId = scene.materials.add(std::move(material));
    Mesh mesh;
    mesh.primitives.push_back(quadPrimitive(materialId));
    Node quad;
    quad.name = "quad";
    quad.component = MeshInstance{scene.meshes.add(std::move(mesh))};
    scene.addNode(std::move(quad));
    addCamera(scene, 3.0f);
    return scene;
}

// `count` wavy grids of n x n quads (2 n^2 triangles each), side by side, each its own mesh: a
// preparation builds `count` mesh BVHs and can stop between two of them.
inline Scene manyGridsScene(int count, int n) {
    Scene scene;
    for (int g = 0; g < count; ++g) {
        Primitive p;
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                const float x = float(i) / float(n), z = float(j) / float(n);
                p.positions.push_back({x, 0.05f * std::sin(13.0f * x + float(g)) * std::cos(11.0f * z), z});
            }
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const auto v = static_cast<std::uint32_t>(j * (n + 1) + i);
                const auto row = static_cast<std::uint32_t>(n + 1);
                p.indices.insert(p.indices.end(), {v, v + row, v + 1, v + 1, v + row, v + row + 1});
            }
        Mesh mesh;
        mesh.primitives.push_back(std::move(p));
        Node node;
        node.name = "grid " + std::to_string(g);
        node.local.translation = {float(g % 8) * 1.1f - 4.4f, -0.5f, float(g / 8) * 1.1f - 3.0f};
        node.component = MeshInstance{scene.meshes.add(std::move(mesh))};
        scene.addNode(std::move(node));
    }
    addCamera(scene, 6.0f);
    return scene;
}

} // namespace glint::test
