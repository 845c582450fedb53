#include "assimp_read.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <string>

namespace glint {

namespace {
// GenSmoothNormals only fills meshes that have no normals, so authored normals survive.
// FlipUVs: Assimp's texture origin is bottom-left, glTF's is top-left.
constexpr unsigned kPostProcess = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_GenSmoothNormals |
                                  aiProcess_SortByPType | aiProcess_ValidateDataStructure | aiProcess_FlipUVs;
// Assimp's messages often repeat the full path; the error already names the file.
std::string withoutPath(std::string message, const std::filesystem::path& file) {
    const std::string path = file.string();
    const std::string name = file.filename().string();
    for (auto at = message.find(path); !path.empty() && at != std::string::npos; at = message.find(path, at + name.size()))
        message.replace(at, path.size(), name);
    return message;
}

} // namespace

LoadResult readWithAssimp(const std::filesystem::path& file, const ConvertOptions& options) {
    Assimp::Importer importer;
    // FBX units are converted by convertAssimpScene from the file's UnitScaleFactor, so Assimp
    // must leave them alone (AI_CONFIG_FBX_CONVERT_TO_M stays off). Collada's <unit> and <up_axis>
    // Assimp applies itself, to the root node.
    importer.SetPropertyBool(AI_CONFIG_FBX_CONVERT_TO_M, false);
    const aiScene* scene = importer.ReadFile(file.string(), kPostProcess);
    if (!scene) throw FileError(file.string(), "import-failed", withoutPath(importer.GetErrorString(), file));
    return convertAssimpScene(*scene, options);
}

} // namespace glint
