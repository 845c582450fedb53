#include "bench_scenes.h"

#include "renderer/gpu_scene/visibility.h"

#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace glint::bench {
namespace {

// OBJ face corners are "i", "i/t", "i//n" or "i/t/n", 1-based or negative (relative to the end).
std::uint32_t cornerIndex(const std::string& corner, std::size_t vertexCount) {
    const long value = std::stol(corner.substr(0, corner.find('/')));
    const long index = value < 0 ? static_cast<long>(vertexCount) + value : value - 1;
    if (index < 0 || index >= static_cast<long>(vertexCount)) throw std::out_of_range("face index");
    return static_cast<std::uint32_t>(index);
}

MaterialId materialOf(const Scene& scene, const std::string& nodeName) {
    const auto id = scene.findByName(nodeName);
    const MeshInstance* instance = id ? scene.at(*id).get<MeshInstance>() : nullptr;
    if (!instance || !scene.meshes.contains(instance->mesh) || scene.meshes.at(instance->mesh).primitives.empty())
        throw std::runtime_error("the room has no mesh node '" + nodeName + "'");
    return scene.meshes.at(instance->mesh).primitives.front().material;
}

// Removed, not hidden: the scene written for Blender (--write-scenes) must hold what Glint renders,
// and Blender's importer does not read Glint's visibility flag.
void removeNode(Scene& scene, const std::string& nodeName) {
    if (const auto id = scene.findByName(nodeName)) scene.removeLeaf(*id);
}

} // namespace

Mesh loadObjMesh(const std::filesystem::path& file, MaterialId material) {
    std::ifstream in(file);
    if (!in) throw std::runtime_error(file.string() + ": cannot open");
    Primitive primitive;
    primitive.material = material;
    std::string line;
    try {
        while (std::getline(in, line)) {
            std::istringstream words(line);
            std::string tag;
            words >> tag;
            if (tag == "v") {
                glm::vec3 p;
                words >> p.x >> p.y >> p.z;
                primitive.positions.push_back(p);
            } else if (tag == "f") {
                std::vector<std::uint32_t> corners;
                for (std::string corner; words >> corner;) corners.push_back(cornerIndex(corner, primitive.positions.size()));
                for (std::size_t i = 2; i < corners.size(); ++i)
                    primitive.indices.insert(primitive.indices.end(), {corners[0], corners[i - 1], corners[i]});
            }
        }
    } catch (const std::exception&) {
        throw std::runtime_error(file.string() + ": bad line '" + line + "'");
    }
    if (primitive.indices.empty()) throw std::runtime_error(file.string() + ": no triangles");
    Mesh mesh;
    mesh.name = file.stem().string();
    mesh.primitives.push_back(std::move(primitive));
    return mesh;
}

Scene bunnyRoom(Scene room, Mesh bunny, int copies) {
    removeNode(room, "short_block");
    removeNode(room, "tall_block");
    for (Primitive& p : bunny.primitives) p.material = materialOf(room, "floor");
    glm::vec3 low(std::numeric_limits<float>::max()), high(-std::numeric_limits<float>::max());
    for (const Primitive& p : bunny.primitives)
        for (const glm::vec3& v : p.positions) low = glm::min(low, v), high = glm::max(high, v);
    const int side = static_cast<int>(std::lround(std::sqrt(copies)));
    if (side * side != copies) throw std::invalid_argument("bunnyRoom: copies must be a square number");
    // The room's floor spans about 0..0.55 m in x and z: one bunny 0.3 m wide, or a grid of smaller ones.
    const float cell = 0.44f / static_cast<float>(side);
    const float scale = (side == 1 ? 0.3f : 0.75f * cell) / (high.x - low.x);
    const MeshId mesh = room.meshes.add(std::move(bunny));
    for (int i = 0; i < copies; ++i) {
        const float cx = 0.278f + cell * (static_cast<float>(i % side) - 0.5f * static_cast<float>(side - 1));
        const float cz = 0.300f + cell * (static_cast<float>(i / side) - 0.5f * static_cast<float>(side - 1));
        const glm::vec3 centre = 0.5f * (low + high) * scale;
        Node node;
        node.name = "bunny_" + std::to_string(i);
        node.local.scale = glm::vec3(scale);
        // Turned by a different angle each (about the bunny's own centre), so copies do not line up.
        node.local.rotation = glm::angleAxis(0.7f * static_cast<float>(i), glm::vec3(0.0f, 1.0f, 0.0f));
        const glm::vec3 turnedCentre = node.local.rotation * centre;
        node.local.translation = glm::vec3(cx - turnedCentre.x, -low.y * scale, cz - turnedCentre.z);
        node.component = MeshInstance{mesh};
        room.addNode(std::move(node));
    }
    return room;
}

std::size_t visibleTriangles(const Scene& scene) {
    std::size_t count = 0;
    for (const NodeId id : scene.depthFirst()) {
        const Node& node = scene.at(id);
        const MeshInstance* instance = node.get<MeshInstance>();
        if (instance && renderer::visibleInWorld(scene, node) && scene.meshes.contains(instance->mesh))
            count += scene.meshes.at(instance->mesh).triangleCount();
    }
    return count;
}

std::vector<BenchScene> benchScenes(const Scene& cornellBox, const std::filesystem::path& bunnyObj) {
    const Mesh bunny = loadObjMesh(bunnyObj, MaterialId{});
    std::vector<BenchScene> scenes;
    scenes.push_back({"cornell_box", cornellBox, 0});
    scenes.push_back({"bunny_room", bunnyRoom(cornellBox, bunny, 1), 0});
    scenes.push_back({"bunnies_16", bunnyRoom(cornellBox, bunny, 16), 0});
    for (BenchScene& s : scenes) s.triangles = visibleTriangles(s.scene);
    return scenes;
}

} // namespace glint::bench
