#pragma once
// Internal to the glTF reader: the steps of one load and the state they share.
// Order: split the container (GLB or text) -> parse the JSON with a depth cap -> validate structure,
// references and byte ranges -> let tinygltf load buffers and images through confined callbacks ->
// convert to a Scene (images, materials, meshes, nodes, animations).
#include "scene/io/scene_io.h"

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace glint {

struct ConfinedFolder;

// The JSON text and, for a GLB, its BIN chunk.
struct GltfSource {
    std::string_view json;
    std::optional<std::span<const std::uint8_t>> bin; // GLB only
    bool glb = false;
};

// Throws FileError: empty-file, truncated-glb, glb-chunk-out-of-range, invalid-glb.
GltfSource splitGltfContainer(std::span<const std::uint8_t> bytes, const std::string& file);

// Refuses nesting deeper than maxDepth before any recursive parser sees the text (json-too-deep),
// then parses (invalid-json) and checks the top level is an object (wrong-type).
nlohmann::json parseGltfJson(std::string_view text, const std::string& file, int maxDepth);

// Types of the members Glint and tinygltf rely on, and every index into another array (dangling-index).
void validateGltfReferences(const nlohmann::json& doc, const std::string& file);

// extensionsRequired, buffers (files, data: URIs, sizes), bufferView and accessor byte ranges, image URIs.
void validateGltfData(const nlohmann::json& doc, const GltfSource& source, const ConfinedFolder& folder,
                      const std::string& file, const LoadOptions& options);

// tinygltf's model with buffers loaded; images keep their encoded bytes (tinygltf::Image::image).
tinygltf::Model loadWithTinygltf(std::span<const std::uint8_t> bytes, const GltfSource& source,
                                 ConfinedFolder& folder, const std::string& file);

struct GltfReadContext {
    std::string file;
    const LoadOptions& options;
    const nlohmann::json& doc;
    const tinygltf::Model& model;
    Scene scene;
    Warnings warnings;
    // glTF index -> Glint id (invalid: not loaded).
    std::vector<ImageId> imageIds;
    std::vector<SamplerId> samplerIds;
    std::vector<TextureId> textureIds;
    std::vector<MaterialId> materialIds;
    std::vector<MeshId> meshIds;
    std::vector<NodeId> nodeIds;

    [[noreturn]] void fail(const std::string& code, const std::string& message) const { throw FileError(file, code, message); }
    void warn(const std::string& code, const std::string& message) { warnings.push_back({file, code, message}); }
    // Something the file holds that Glint cannot keep: a warning now, named again by the next save.
    void drop(const std::string& code, const std::string& message)
    {
        warn(code, message);
        scene.unsupported.push_back({file, code, message});
    }
};

void readImagesAndTextures(GltfReadContext& ctx);
void readMaterials(GltfReadContext& ctx);
void readMeshes(GltfReadContext& ctx);
void readNodes(GltfReadContext& ctx);
void readAnimations(GltfReadContext& ctx);
void noteDroppedMembers(GltfReadContext& ctx);

} // namespace glint
