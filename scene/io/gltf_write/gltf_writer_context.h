#pragma once
// State shared by the parts of the glTF writer (nodes, meshes, materials, animations) while one
// scene is written. Asset ids map to glTF indices in id order, so a saved file is ordered by id.
#include "gltf_writer.h"
#include "gltf_writer_buffers.h"
#include "scene/io/json/json_numbers.h" // mergeUnknown: `unknown` is {"extensions": {...}, "extras": ...}

#include <map>
#include <string>

namespace glint {

template <class IdT>
using IndexOf = std::map<IdT, int>;

struct GltfWriteContext {
    GltfWriteContext(const Scene& s, GltfWriteOptions o) : scene(s), options(std::move(o)) {}

    const Scene& scene;
    GltfWriteOptions options;
    nlohmann::json root = nlohmann::json::object();
    GltfBufferBuilder buffers;
    IndexOf<NodeId> nodes;
    IndexOf<MeshId> meshes;
    IndexOf<MaterialId> materials;
    IndexOf<TextureId> textures;
    IndexOf<ImageId> images;
    IndexOf<SamplerId> samplers;
    std::vector<ExternalFile> externalImages;
    // Materials the writer makes (an area light's emission), written after the scene's materials.
    std::vector<nlohmann::json> generatedMaterials;
    Warnings dropped;

    void drop(const std::string& code, const std::string& message) { dropped.push_back({options.displayName, code, message}); }
};

// Each part appends its arrays to ctx.root; called in this order so the buffer is laid out
// meshes, shape fallback meshes, animations, images.
void writeMeshes(GltfWriteContext& ctx);
void writeNodes(GltfWriteContext& ctx);       // nodes, scene, cameras, lights, shape and area light fallback meshes
void writeAnimations(GltfWriteContext& ctx);  // the scene's animations, then baked camera paths
void writeMaterials(GltfWriteContext& ctx);   // materials (then generated ones), textures, samplers
void writeImages(GltfWriteContext& ctx);

// A mesh as glTF JSON, its data appended to the buffer (also used for shape fallback meshes).
nlohmann::json meshJson(GltfWriteContext& ctx, const Mesh& mesh, const std::string& what);

} // namespace glint
