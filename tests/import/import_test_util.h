#pragma once
// Helpers the import suites share: world-space positions and small files in a temporary folder.
#include "scene/core/scene.h"

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace glint::test {

inline void writeText(const std::filesystem::path& file, const std::string& text) {
    std::ofstream(file, std::ios::binary) << text;
}

inline std::vector<std::uint8_t> readBytes(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Every mesh instance's positions in world space, in node order.
inline std::vector<glm::vec3> worldPositions(const Scene& scene) {
    std::vector<glm::vec3> out;
    for (NodeId id : scene.depthFirst()) {
        const auto* instance = scene.at(id).get<MeshInstance>();
        if (!instance) continue;
        const glm::mat4 worldFromLocal = scene.worldFromNode(id);
        for (const Primitive& p : scene.meshes.at(instance->mesh).primitives)
            for (glm::vec3 v : p.positions) out.push_back(glm::vec3(worldFromLocal * glm::vec4(v, 1.0f)));
    }
    return out;
}

inline std::size_t totalTriangles(const Scene& scene) {
    std::size_t n = 0;
    for (const auto& [id, mesh] : scene.meshes) n += mesh.triangleCount();
    return n;
}

inline std::size_t totalVertices(const Scene& scene) {
    std::size_t n = 0;
    for (const auto& [id, mesh] : scene.meshes)
        for (const Primitive& p : mesh.primitives) n += p.positions.size();
    return n;
}

inline bool hasWarning(const Warnings& warnings, const std::string& code) {
    for (const Warning& w : warnings)
        if (w.code == code) return true;
    return false;
}

} // namespace glint::test
