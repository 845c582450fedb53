#include "assimp_convert.h"

#include "assimp_axes.h"
#include "assimp_cameras_lights.h"
#include "assimp_materials.h"
#include "assimp_meshes.h"
#include "assimp_textures.h"

#include <assimp/scene.h>

#include <map>
#include <vector>

namespace glint {

namespace {

// Assimp matrices are row-major with the translation in the fourth column.
glm::mat4 toGlm(const aiMatrix4x4& m) {
    return glm::transpose(glm::mat4(m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3, m.d4));
}

// What the conversion could not keep, counted so that each kind is reported once.
struct Dropped {
    std::size_t faces = 0;
    std::size_t nonFiniteTriangles = 0;
    std::size_t skinnedMeshes = 0;
    std::size_t morphedMeshes = 0;
    std::size_t lights = 0;   // area and ambient lights, and lights or cameras on no node
    std::size_t cameras = 0;
};

class SceneBuilder {
public:
    SceneBuilder(const aiScene& ai, const ConvertOptions& options)
        : ai_(ai), options_(options), file_(options.sourceFile.string()),
          textures_(ai, result_.scene, options.sourceFile, options.maxTextureBytes, result_.warnings) {}

    LoadResult build() {
        result_.scene.name = options_.sourceFile.stem().string();
        for (unsigned i = 0; i < ai_.mNumMaterials; ++i)
            materials_.push_back(result_.scene.materials.add(convertMaterial(*ai_.mMaterials[i], textures_, result_.warnings, file_)));
        addNodes();
        if (triangles_ == 0) throw FileError(file_, "no-geometry", "the file contains no triangles");
        reportDropped();
        return std::move(result_);
    }

private:
    void addNodes() {
        collectCamerasAndLights();
        std::vector<std::pair<const aiNode*, NodeId>> stack{{ai_.mRootNode, NodeId{}}};
        while (!stack.empty()) {
            auto [source, parent] = stack.back();
            stack.pop_back();
            Node node = convertNode(*source, !parent);
            std::vector<ImportedComponent> extras = takeCamerasAndLights(*source);
            // A node without a mesh takes its one camera or light itself, as glTF files have it;
            // otherwise each goes to a child, as the glTF reader splits such nodes.
            if (std::holds_alternative<std::monostate>(node.component) && extras.size() == 1) {
                node.local = fromMatrix(toMatrix(node.local) * extras.front().nodeFromComponent);
                node.component = extras.front().component;
                extras.clear();
            }
            const std::string name = node.name;
            const NodeId id = result_.scene.addNode(std::move(node), parent);
            for (const ImportedComponent& extra : extras) {
                Node child;
                child.name = name + (std::holds_alternative<Camera>(extra.component) ? ".camera" : ".light");
                child.local = fromMatrix(extra.nodeFromComponent);
                child.component = extra.component;
                result_.scene.addNode(std::move(child), id);
            }
            for (unsigned i = source->mNumChildren; i-- > 0;) stack.emplace_back(source->mChildren[i], id);
        }
        dropped_.cameras += cameraByName_.size();
        dropped_.lights += lightByName_.size();
    }

    void collectCamerasAndLights() {
        for (unsigned i = 0; i < ai_.mNumCameras; ++i) cameraByName_.emplace(ai_.mCameras[i]->mName.C_Str(), ai_.mCameras[i]);
        for (unsigned i = 0; i < ai_.mNumLights; ++i) lightByName_.emplace(ai_.mLights[i]->mName.C_Str(), ai_.mLights[i]);
    }

    // Each camera and light goes to a node of its name (Assimp links them by name), in file order;
    // what finds no node is reported.
    std::vector<ImportedComponent> takeCamerasAndLights(const aiNode& node) {
        std::vector<ImportedComponent> found;
        const std::string name = node.mName.C_Str();
        if (auto it = cameraByName_.find(name); it != cameraByName_.end()) {
            found.push_back(convertCamera(*it->second));
            cameraByName_.erase(it);
        }
        if (auto it = lightByName_.find(name); it != lightByName_.end()) {
            if (auto light = convertLight(*it->second)) {
                found.push_back(*light);
                ++lightsKept_;
            } else {
                ++dropped_.lights;
            }
            lightByName_.erase(it);
        }
        return found;
    }

    Node convertNode(const aiNode& source, bool isRoot) {
        Node node;
        node.name = source.mName.C_Str();
        glm::mat4 parentFromLocal = toGlm(source.mTransformation);
        if (isRoot) {
            parentFromLocal = glintFromFileAxes(ai_.mMetaData, file_, result_.warnings) * parentFromLocal;
            if (node.name.empty()) node.name = options_.sourceFile.filename().string();
        }
        node.local = fromMatrix(parentFromLocal);
        if (source.mNumMeshes > 0)
            if (MeshId mesh = meshFor(source); mesh.valid()) node.component = MeshInstance{mesh};
        return node;
    }

    // Nodes naming the same Assimp meshes share one glint mesh (instancing).
    MeshId meshFor(const aiNode& node) {
        std::vector<unsigned> key(node.mMeshes, node.mMeshes + node.mNumMeshes);
        if (auto it = meshes_.find(key); it != meshes_.end()) return it->second;
        Mesh mesh;
        mesh.name = ai_.mMeshes[key.front()]->mName.length ? ai_.mMeshes[key.front()]->mName.C_Str() : node.mName.C_Str();
        for (unsigned index : key) addPrimitive(*ai_.mMeshes[index], mesh);
        MeshId id = mesh.primitives.empty() ? MeshId{} : result_.scene.meshes.add(std::move(mesh));
        return meshes_[key] = id;
    }

    void addPrimitive(const aiMesh& source, Mesh& mesh) {
        const MaterialId material = source.mMaterialIndex < materials_.size() ? materials_[source.mMaterialIndex] : MaterialId{};
        PrimitiveConversion converted = convertPrimitive(source, material);
        dropped_.faces += converted.droppedFaces;
        dropped_.nonFiniteTriangles += converted.nonFiniteTriangles;
        dropped_.skinnedMeshes += source.HasBones() ? 1 : 0;
        dropped_.morphedMeshes += source.mNumAnimMeshes > 0 ? 1 : 0;
        if (converted.primitive.indices.empty()) return;
        triangles_ += converted.primitive.triangleCount();
        if (triangles_ > options_.maxTriangles)
            throw FileError(file_, "too-many-triangles", "more than " + std::to_string(options_.maxTriangles) + " triangles");
        mesh.primitives.push_back(std::move(converted.primitive));
    }

    void warnIf(bool condition, const std::string& code, const std::string& message) {
        if (condition) result_.warnings.push_back({file_, code, message});
    }

    void reportDropped() {
        warnIf(dropped_.faces > 0, "non-triangles-dropped", std::to_string(dropped_.faces) + " point and line primitives dropped (triangles only)");
        warnIf(dropped_.nonFiniteTriangles > 0, "non-finite-position",
               std::to_string(dropped_.nonFiniteTriangles) + " triangles with NaN or infinite positions dropped");
        warnIf(dropped_.skinnedMeshes > 0, "skin-dropped", std::to_string(dropped_.skinnedMeshes) + " skinned meshes imported as static geometry");
        warnIf(dropped_.morphedMeshes > 0, "morph-targets-dropped", std::to_string(dropped_.morphedMeshes) + " meshes lost their morph targets");
        warnIf(ai_.mNumAnimations > 0, "animation-dropped", std::to_string(ai_.mNumAnimations) + " animations dropped");
        warnIf(dropped_.lights > 0, "lights-dropped", std::to_string(dropped_.lights) + " lights dropped (area, ambient, or on no node)");
        warnIf(dropped_.cameras > 0, "cameras-dropped", std::to_string(dropped_.cameras) + " cameras dropped (on no node)");
        warnIf(lightsKept_ > 0, "light-units-unknown",
               "light intensities are taken as given: Assimp does not say their units, so check the brightness");
    }

    const aiScene& ai_;
    const ConvertOptions& options_;
    std::string file_;
    LoadResult result_;
    TextureImporter textures_;
    std::vector<MaterialId> materials_;
    std::map<std::vector<unsigned>, MeshId> meshes_;
    std::uint64_t triangles_ = 0;
    Dropped dropped_;
    std::multimap<std::string, const aiCamera*> cameraByName_;
    std::multimap<std::string, const aiLight*> lightByName_;
    std::size_t lightsKept_ = 0;
};

} // namespace

LoadResult convertAssimpScene(const aiScene& scene, const ConvertOptions& options) {
    if (!scene.mRootNode) throw FileError(options.sourceFile.string(), "no-geometry", "the file has no scene graph");
    return SceneBuilder(scene, options).build();
}

} // namespace glint
