#pragma once
#include "ids.h"

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <limits>
#include <string>

namespace glint {

// KHR_texture_transform. Applied as uv' = T * R * S * uv (the extension's order).
struct TextureTransform {
    glm::vec2 offset{0.0f};
    float rotation = 0.0f; // radians, counter-clockwise
    glm::vec2 scale{1.0f};
    int texCoord = -1;     // -1: keep the TextureRef's texCoord

    bool isIdentity() const { return offset == glm::vec2(0.0f) && rotation == 0.0f && scale == glm::vec2(1.0f) && texCoord < 0; }
    friend bool operator==(const TextureTransform&, const TextureTransform&) = default;
};

struct TextureRef {
    TextureId texture{};
    int texCoord = 0;
    float scale = 1.0f; // normalTexture.scale or occlusionTexture.strength; 1 elsewhere
    TextureTransform transform;
    nlohmann::json unknown; // extensions/extras on the textureInfo that Glint does not understand

    bool valid() const { return texture.valid(); }
    friend bool operator==(const TextureRef&, const TextureRef&) = default;
};

enum class AlphaMode { Opaque, Mask, Blend };

// glTF metallic-roughness plus the KHR_materials_* extensions Glint renders.
// Defaults are the glTF defaults, so an empty glTF material and Material{} agree.
struct Material {
    std::string name;

    glm::vec4 baseColorFactor{1.0f};
    TextureRef baseColorTexture;
    float metallicFactor = 1.0f;
    float roughnessFactor = 1.0f;
    TextureRef metallicRoughnessTexture;
    TextureRef normalTexture;
    TextureRef occlusionTexture;

    glm::vec3 emissiveFactor{0.0f};
    TextureRef emissiveTexture;
    float emissiveStrength = 1.0f; // KHR_materials_emissive_strength

    // KHR_materials_specular: specularFactor 0 gives a pure Lambert surface.
    float specularFactor = 1.0f;
    TextureRef specularTexture;
    glm::vec3 specularColorFactor{1.0f};
    TextureRef specularColorTexture;

    float transmissionFactor = 0.0f; // KHR_materials_transmission
    TextureRef transmissionTexture;
    float ior = 1.5f; // KHR_materials_ior

    // KHR_materials_volume: thickness 0 means thin-walled (no refraction bending).
    float thicknessFactor = 0.0f;
    TextureRef thicknessTexture;
    float attenuationDistance = std::numeric_limits<float>::infinity();
    glm::vec3 attenuationColor{1.0f};
    // GLINT_materials_volume_scatter: of the attenuation above (the extinction), the share
    // scattered per channel (the single-scattering albedo; 0: absorption only, as
    // KHR_materials_volume alone), scattered with a Henyey-Greenstein lobe of anisotropy g.
    glm::vec3 scatterColor{0.0f};
    float scatterAnisotropy = 0.0f;

    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    bool doubleSided = false;

    nlohmann::json unknown; // {"extensions": {...}, "extras": ...} that Glint does not interpret

    friend bool operator==(const Material&, const Material&) = default;
};

} // namespace glint
