#pragma once
// Turns the textures Assimp's materials name into glint images, textures and samplers.
// External files are referenced relative to the model's folder and may not leave it (symlinks are
// resolved first); their bytes are read here so that the imported scene is self-contained.
// Embedded textures (FBX, some OBJ/3DS exporters) keep their encoded bytes. Only PNG and JPEG can
// travel in glTF: anything else becomes a missing-texture placeholder with a warning.
#include "scene/core/diagnostics.h"
#include "scene/core/material.h"
#include "scene/core/scene.h"

#include <assimp/material.h>

#include <filesystem>
#include <map>
#include <string>
#include <tuple>

struct aiScene;

namespace glint {

class TextureImporter {
public:
    TextureImporter(const aiScene& ai, Scene& scene, const std::filesystem::path& sourceFile,
                    std::uint64_t maxTextureBytes, Warnings& warnings);

    // The material's first texture of `type`, or an invalid TextureRef when it has none.
    TextureRef reference(const aiMaterial& material, aiTextureType type);

private:
    ImageId imageFor(const std::string& path);
    Image embeddedImage(const std::string& path);
    Image externalImage(const std::string& path);
    SamplerId samplerFor(Wrap s, Wrap t);
    void warn(const std::string& code, const std::string& message);

    const aiScene& ai_;
    Scene& scene_;
    std::filesystem::path folder_;
    std::string fileName_;
    std::uint64_t maxTextureBytes_;
    Warnings& warnings_;
    std::map<std::string, ImageId> images_;
    std::map<std::tuple<ImageId, Wrap, Wrap>, TextureId> textures_;
    std::map<std::pair<Wrap, Wrap>, SamplerId> samplers_;
};

} // namespace glint
