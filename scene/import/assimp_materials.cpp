#include "assimp_materials.h"

#include <assimp/material.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace glint {

namespace {

std::optional<float> getFloat(const aiMaterial& m, const char* key, unsigned type, unsigned index) {
    ai_real value = 0;
    if (m.Get(key, type, index, value) != AI_SUCCESS || !std::isfinite(value)) return std::nullopt;
    return static_cast<float>(value);
}

std::optional<glm::vec4> getColor(const aiMaterial& m, const char* key, unsigned type, unsigned index) {
    aiColor4D c;
    if (m.Get(key, type, index, c) != AI_SUCCESS) return std::nullopt;
    glm::vec4 v(c.r, c.g, c.b, c.a);
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z) || !std::isfinite(v.w)) return std::nullopt;
    return v;
}

float maxComponent(glm::vec3 v) { return std::max({v.x, v.y, v.z}); }

bool isPbr(const aiMaterial& m) {
    return getFloat(m, AI_MATKEY_METALLIC_FACTOR) || getFloat(m, AI_MATKEY_ROUGHNESS_FACTOR);
}

void applyPhongSpecular(const aiMaterial& m, Material& out, TextureImporter& textures) {
    out.metallicFactor = 0.0f;
    auto shininess = getFloat(m, AI_MATKEY_SHININESS);
    out.roughnessFactor = shininess && *shininess > 0.0f ? roughnessFromShininess(*shininess) : 1.0f;
    if (auto specular = getColor(m, AI_MATKEY_COLOR_SPECULAR)) {
        const glm::vec3 ks = glm::max(glm::vec3(*specular), glm::vec3(0.0f));
        const float intensity = maxComponent(ks) * getFloat(m, AI_MATKEY_SHININESS_STRENGTH).value_or(1.0f);
        out.specularFactor = std::clamp(intensity, 0.0f, 1.0f);
        out.specularColorFactor = maxComponent(ks) > 0.0f ? ks / maxComponent(ks) : glm::vec3(1.0f);
    }
    out.specularColorTexture = textures.reference(m, aiTextureType_SPECULAR);
}

void applyPhong(const aiMaterial& m, Material& out, TextureImporter& textures) {
    if (auto diffuse = getColor(m, AI_MATKEY_COLOR_DIFFUSE)) out.baseColorFactor = glm::vec4(glm::vec3(*diffuse), 1.0f);
    out.baseColorTexture = textures.reference(m, aiTextureType_DIFFUSE);
    applyPhongSpecular(m, out, textures);
    const float opacity = std::clamp(getFloat(m, AI_MATKEY_OPACITY).value_or(1.0f), 0.0f, 1.0f);
    out.transmissionFactor = 1.0f - opacity;
}

void applyPbr(const aiMaterial& m, Material& out, TextureImporter& textures, Warnings& warnings, const std::string& file) {
    if (auto base = getColor(m, AI_MATKEY_BASE_COLOR)) out.baseColorFactor = *base;
    else if (auto diffuse = getColor(m, AI_MATKEY_COLOR_DIFFUSE)) out.baseColorFactor = *diffuse;
    out.baseColorTexture = textures.reference(m, aiTextureType_BASE_COLOR);
    if (!out.baseColorTexture.valid()) out.baseColorTexture = textures.reference(m, aiTextureType_DIFFUSE);
    out.metallicFactor = std::clamp(getFloat(m, AI_MATKEY_METALLIC_FACTOR).value_or(1.0f), 0.0f, 1.0f);
    out.roughnessFactor = std::clamp(getFloat(m, AI_MATKEY_ROUGHNESS_FACTOR).value_or(1.0f), 0.0f, 1.0f);
    // glTF packs metalness (blue) and roughness (green) into one texture; Assimp reports the glTF
    // texture under both types, other formats may have two separate images that cannot be kept.
    TextureRef metal = textures.reference(m, aiTextureType_METALNESS);
    TextureRef rough = textures.reference(m, aiTextureType_DIFFUSE_ROUGHNESS);
    if (metal.valid() && (!rough.valid() || rough.texture == metal.texture)) out.metallicRoughnessTexture = metal;
    else if (metal.valid() || rough.valid())
        warnings.push_back({file, "texture-dropped", "material '" + out.name + "': separate metalness and roughness textures cannot be kept; factors used"});
    out.transmissionFactor = std::clamp(getFloat(m, AI_MATKEY_TRANSMISSION_FACTOR).value_or(0.0f), 0.0f, 1.0f);
    out.transmissionTexture = textures.reference(m, aiTextureType_TRANSMISSION);
    out.occlusionTexture = textures.reference(m, aiTextureType_AMBIENT_OCCLUSION);
}

void applyEmissive(const aiMaterial& m, Material& out, TextureImporter& textures) {
    glm::vec3 emissive = glm::max(glm::vec3(getColor(m, AI_MATKEY_COLOR_EMISSIVE).value_or(glm::vec4(0.0f))), glm::vec3(0.0f));
    out.emissiveTexture = textures.reference(m, aiTextureType_EMISSIVE);
    // An emission map with no emissive colour (OBJ map_Ke without Ke) would otherwise be black.
    if (out.emissiveTexture.valid() && maxComponent(emissive) == 0.0f) emissive = glm::vec3(1.0f);
    const float strength = std::max(maxComponent(emissive), 1.0f) * std::max(getFloat(m, AI_MATKEY_EMISSIVE_INTENSITY).value_or(1.0f), 0.0f);
    out.emissiveFactor = emissive / std::max(maxComponent(emissive), 1.0f);
    out.emissiveStrength = strength;
}

void applySurface(const aiMaterial& m, Material& out, TextureImporter& textures, Warnings& warnings, const std::string& file) {
    out.normalTexture = textures.reference(m, aiTextureType_NORMALS);
    if (!out.normalTexture.valid() && m.GetTextureCount(aiTextureType_HEIGHT) > 0)
        warnings.push_back({file, "bump-map-dropped", "material '" + out.name + "': bump (height) maps are not supported; dropped"});
    if (m.GetTextureCount(aiTextureType_OPACITY) > 0)
        warnings.push_back({file, "texture-dropped", "material '" + out.name + "': opacity textures are not supported; dropped"});
    int twoSided = 0;
    if (m.Get(AI_MATKEY_TWOSIDED, twoSided) == AI_SUCCESS) out.doubleSided = twoSided != 0;
}

} // namespace

float roughnessFromShininess(float shininess) {
    return std::clamp(std::sqrt(2.0f / (std::max(shininess, 0.0f) + 2.0f)), 0.0f, 1.0f);
}

Material convertMaterial(const aiMaterial& m, TextureImporter& textures, Warnings& warnings, const std::string& file) {
    Material out;
    aiString name;
    if (m.Get(AI_MATKEY_NAME, name) == AI_SUCCESS) out.name = name.C_Str();
    if (isPbr(m)) applyPbr(m, out, textures, warnings, file);
    else applyPhong(m, out, textures);
    applyEmissive(m, out, textures);
    applySurface(m, out, textures, warnings, file);
    return out;
}

} // namespace glint
