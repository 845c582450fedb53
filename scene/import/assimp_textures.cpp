#include "assimp_textures.h"

#include <assimp/scene.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <optional>
#include <span>
#include <system_error>

namespace glint {

namespace {

std::string mimeTypeOf(std::span<const std::uint8_t> bytes) {
    static constexpr std::uint8_t png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (bytes.size() >= 8 && std::memcmp(bytes.data(), png, 8) == 0) return "image/png";
    if (bytes.size() >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF) return "image/jpeg";
    return {};
}

Wrap wrapFrom(aiTextureMapMode mode) {
    switch (mode) {
    case aiTextureMapMode_Mirror: return Wrap::MirroredRepeat;
    case aiTextureMapMode_Clamp:
    case aiTextureMapMode_Decal: return Wrap::ClampToEdge;
    default: return Wrap::Repeat;
    }
}

// Windows exporters write "C:\..." and backslashes; both are read as paths of this machine.
bool isAbsolutePath(const std::string& path) {
    return !path.empty() && (path[0] == '/' || (path.size() > 1 && path[1] == ':'));
}

bool isInside(const std::filesystem::path& folder, const std::filesystem::path& inner) {
    auto i = inner.begin();
    for (auto f = folder.begin(); f != folder.end(); ++f, ++i)
        if (i == inner.end() || *f != *i) return false;
    return true;
}

std::optional<std::vector<std::uint8_t>> readBytes(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return std::nullopt;
    std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) return std::nullopt;
    return bytes;
}

} // namespace

TextureImporter::TextureImporter(const aiScene& ai, Scene& scene, const std::filesystem::path& sourceFile,
                                 std::uint64_t maxTextureBytes, Warnings& warnings)
    : ai_(ai), scene_(scene), folder_(sourceFile.parent_path()), fileName_(sourceFile.string()),
      maxTextureBytes_(maxTextureBytes), warnings_(warnings) {}

void TextureImporter::warn(const std::string& code, const std::string& message) {
    warnings_.push_back({fileName_, code, message});
}

TextureRef TextureImporter::reference(const aiMaterial& material, aiTextureType type) {
    if (material.GetTextureCount(type) == 0) return {};
    aiString path;
    unsigned uvChannel = 0;
    aiTextureMapMode modes[2] = {aiTextureMapMode_Wrap, aiTextureMapMode_Wrap};
    if (material.GetTexture(type, 0, &path, nullptr, &uvChannel, nullptr, nullptr, modes) != AI_SUCCESS) return {};

    const ImageId image = imageFor(path.C_Str());
    const Wrap s = wrapFrom(modes[0]);
    const Wrap t = wrapFrom(modes[1]);
    auto [it, added] = textures_.try_emplace({image, s, t});
    if (added) it->second = scene_.textures.add(Texture{scene_.images.at(image).name, image, samplerFor(s, t), {}});

    TextureRef ref;
    ref.texture = it->second;
    if (uvChannel > 1) warn("texcoord-dropped", "texture '" + std::string(path.C_Str()) + "' uses UV channel " +
                                                   std::to_string(uvChannel) + "; glTF keeps two, channel 0 used");
    ref.texCoord = uvChannel <= 1 ? static_cast<int>(uvChannel) : 0;
    return ref;
}

SamplerId TextureImporter::samplerFor(Wrap s, Wrap t) {
    if (s == Wrap::Repeat && t == Wrap::Repeat) return {}; // glTF's default sampler
    auto [it, added] = samplers_.try_emplace({s, t});
    if (added) {
        Sampler sampler;
        sampler.wrapS = s;
        sampler.wrapT = t;
        it->second = scene_.samplers.add(sampler);
    }
    return it->second;
}

ImageId TextureImporter::imageFor(const std::string& path) {
    if (auto it = images_.find(path); it != images_.end()) return it->second;
    Image image = ai_.GetEmbeddedTexture(path.c_str()) ? embeddedImage(path) : externalImage(path);
    return images_[path] = scene_.images.add(std::move(image));
}

Image TextureImporter::embeddedImage(const std::string& path) {
    const aiTexture& texture = *ai_.GetEmbeddedTexture(path.c_str());
    Image image;
    image.name = texture.mFilename.length ? std::filesystem::path(texture.mFilename.C_Str()).filename().string() : path;
    if (texture.mHeight != 0) {
        warn("embedded-texture-dropped", "embedded texture '" + path + "' holds raw pixels, which glTF cannot carry; a placeholder is used");
        image.missing = true;
        return image;
    }
    std::span<const std::uint8_t> bytes(reinterpret_cast<const std::uint8_t*>(texture.pcData), texture.mWidth);
    image.mimeType = mimeTypeOf(bytes);
    if (image.mimeType.empty()) {
        warn("unsupported-texture-format", "embedded texture '" + path + "' is neither PNG nor JPEG; a placeholder is used");
        image.missing = true;
        return image;
    }
    image.encoded.assign(bytes.begin(), bytes.end());
    return image;
}

Image TextureImporter::externalImage(const std::string& path) {
    std::string relative = path;
    std::replace(relative.begin(), relative.end(), '\\', '/');
    Image image;
    image.name = std::filesystem::path(relative).filename().string();
    image.uri = relative;
    image.missing = true; // until its bytes are in hand

    std::filesystem::path candidate = folder_ / relative;
    if (isAbsolutePath(relative)) {
        // Exporters often write the author's absolute path; the file usually sits beside the model.
        warn("texture-path-absolute", "texture '" + path + "' has an absolute path; looked for '" + image.name + "' in the model's folder");
        image.uri = image.name;
        candidate = folder_ / image.name;
    }
    std::error_code ec;
    const auto folder = std::filesystem::weakly_canonical(folder_.empty() ? "." : folder_, ec);
    const auto resolved = std::filesystem::weakly_canonical(candidate, ec);
    if (ec || !isInside(folder, resolved)) {
        warn("texture-outside-folder", "texture '" + path + "' lies outside the model's folder and was refused");
        return image;
    }
    if (!std::filesystem::is_regular_file(resolved, ec)) {
        warn("missing-texture", "texture '" + path + "' not found; a placeholder is used");
        return image;
    }
    if (std::filesystem::file_size(resolved, ec) > maxTextureBytes_) {
        warn("texture-too-large", "texture '" + path + "' is larger than " + std::to_string(maxTextureBytes_) + " bytes; a placeholder is used");
        return image;
    }
    auto bytes = readBytes(resolved);
    image.mimeType = bytes ? mimeTypeOf(*bytes) : std::string();
    if (image.mimeType.empty()) {
        warn("unsupported-texture-format", "texture '" + path + "' is not a readable PNG or JPEG; a placeholder is used");
        return image;
    }
    image.encoded = std::move(*bytes);
    image.uri.clear(); // the bytes travel with the scene
    image.missing = false;
    return image;
}

} // namespace glint
