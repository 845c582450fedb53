#pragma once
// Writes a Scene as glTF 2.0 JSON plus one binary buffer (docs/FILE_FORMAT.md).
//
// Why nlohmann::json directly and not tinygltf's writer: tinygltf 2.7 (Debian 12) writes the .bin and
// the .gltf itself with std::ofstream under their final names (SerializeGltfBufferData,
// WriteGltfSceneToFile), which defeats the atomic temporary-name-then-rename save; its Model keeps
// every number as a double, so floats would need the same shortest-decimal step anyway; and unknown
// extensions and extras would pass through tinygltf::Value and back. Building the JSON here keeps the
// output byte-for-byte under our control (sorted keys, shortest float decimals, no locale), and the
// reader still parses with tinygltf.
#include "scene/core/diagnostics.h"
#include "scene/core/scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace glint {

enum class GltfContainer { Text, Binary }; // .gltf (+ .bin + image files) or .glb

// A file beside the .gltf: `uri` as the JSON has it (percent-encoded), `path` the file it names,
// relative to the glTF's folder and checked not to leave it.
struct ExternalFile {
    std::string uri;
    std::string path;
    std::vector<std::uint8_t> bytes;
};

struct GltfOutput {
    std::string json;               // the glTF JSON text
    std::vector<std::uint8_t> bin;  // buffer 0 (.gltf: the file binUri; .glb: the BIN chunk)
    std::string binUri;             // .gltf only; empty when there is no binary data
    std::vector<ExternalFile> images; // .gltf only, in image id order
    Warnings dropped;               // everything that could not be written, each named
};

struct GltfWriteOptions {
    GltfContainer container = GltfContainer::Binary;
    std::string baseName = "scene";   // the .bin is <baseName>.<content hash>.bin
    std::string displayName = "scene.glb"; // names the file in dropped-item warnings
    std::vector<std::string> reservedUris; // names images may not take (the glTF and project file)
};

GltfOutput writeGltf(const Scene& scene, const GltfWriteOptions& options);

// The GLB container: header, JSON chunk (space padded), BIN chunk (zero padded) when there is data.
std::vector<std::uint8_t> glbBytes(const GltfOutput& output);

// The string the asset's "generator" carries: "Glint <version>".
std::string glintGenerator();

} // namespace glint
