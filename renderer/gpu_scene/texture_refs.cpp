#include "renderer/gpu_scene/texture_refs.h"

#include <cmath>

namespace glint::renderer {
namespace {

int wrapCode(Wrap wrap) {
    switch (wrap) {
    case Wrap::ClampToEdge: return 1;
    case Wrap::MirroredRepeat: return 2;
    default: return 0;
    }
}

bool nearestMin(Filter f) { return f == Filter::Nearest || f == Filter::NearestMipmapNearest || f == Filter::NearestMipmapLinear; }

// glTF leaves an unset filter to the viewer: trilinear, like the sample viewer.
bool mipmapped(Filter f) { return f != Filter::Nearest && f != Filter::Linear; }

} // namespace

float samplerFlags(const Sampler& s) {
    const int flags = wrapCode(s.wrapS) + 3 * wrapCode(s.wrapT) + 9 * (s.magFilter == Filter::Nearest ? 1 : 0) +
                      18 * (nearestMin(s.minFilter) ? 1 : 0) + 36 * (mipmapped(s.minFilter) ? 1 : 0);
    return static_cast<float>(flags);
}

void appendTextureRef(std::vector<glm::vec4>& out, const TextureRef& ref, TextureSlot slot, const Sampler& sampler) {
    const TextureTransform& t = ref.transform;
    const float c = std::cos(t.rotation), s = std::sin(t.rotation);
    const int texCoord = t.texCoord >= 0 ? t.texCoord : ref.texCoord;
    out.push_back({static_cast<float>(slot.bucket), static_cast<float>(slot.layer), samplerFlags(sampler), static_cast<float>(texCoord)});
    out.push_back({c * t.scale.x, s * t.scale.y, -s * t.scale.x, c * t.scale.y});
    out.push_back({t.offset.x, t.offset.y, ref.scale, 0.0f});
}

namespace {

// Where the image of `ref` lives in `textures` (no slot when anything is missing).
TextureSlot refSlot(const Scene* scene, const TextureRef& ref, bool srgb, const TextureSet* textures) {
    if (!scene || !textures || !ref.valid() || !scene->textures.contains(ref.texture)) return {};
    return textures->find(scene->textures.at(ref.texture).image, srgb);
}

} // namespace

void appendMaterialTextureRefs(std::vector<glm::vec4>& out, const Scene* scene, const Material& m, const TextureSet* textures) {
    const auto add = [&](const TextureRef& ref, bool srgb) {
        Sampler sampler;
        if (scene && ref.valid() && scene->textures.contains(ref.texture)) {
            const Texture& texture = scene->textures.at(ref.texture);
            if (scene->samplers.contains(texture.sampler)) sampler = scene->samplers.at(texture.sampler);
        }
        appendTextureRef(out, ref, refSlot(scene, ref, srgb, textures), sampler);
    };
    add(m.baseColorTexture, true);
    add(m.metallicRoughnessTexture, false);
    add(m.normalTexture, false);
    add(m.emissiveTexture, true);
    add(m.specularTexture, false);
    add(m.specularColorTexture, true);
    add(m.transmissionTexture, false);
    add(m.thicknessTexture, false);
}

bool hasEmissiveTexture(const Scene& scene, const Material& m) {
    return m.emissiveTexture.valid() && scene.textures.contains(m.emissiveTexture.texture);
}

glm::vec3 sampledEmission(const Scene& scene, const Material& m, const TextureSet* textures) {
    const glm::vec3 factor = m.emissiveFactor * m.emissiveStrength;
    if (!hasEmissiveTexture(scene, m)) return factor;
    if (!textures) return glm::vec3(0.0f);
    const auto mean = textures->meanOf.find({scene.textures.at(m.emissiveTexture.texture).image, true});
    return mean == textures->meanOf.end() ? glm::vec3(0.0f) : factor * mean->second;
}

unsigned extensionTexturesUsed(const Scene& scene, const std::set<MaterialId>& materials, const TextureSet& textures) {
    unsigned mask = 0;
    const auto has = [&](const TextureRef& ref, bool srgb) { return refSlot(&scene, ref, srgb, &textures).bucket >= 0; };
    for (const MaterialId id : materials) {
        if (!scene.materials.contains(id)) continue;
        const Material& m = scene.materials.at(id);
        if (has(m.specularTexture, false) || has(m.specularColorTexture, true)) mask |= specularTextureBit;
        if (has(m.transmissionTexture, false)) mask |= transmissionTextureBit;
        if (has(m.thicknessTexture, false)) mask |= thicknessTextureBit;
    }
    return mask;
}

std::vector<std::string> extensionTextureDefines(unsigned mask) {
    std::vector<std::string> names;
    if (mask & specularTextureBit) names.push_back("HAS_SPECULAR_TEXTURES");
    if (mask & transmissionTextureBit) names.push_back("HAS_TRANSMISSION_TEXTURES");
    if (mask & thicknessTextureBit) names.push_back("HAS_THICKNESS_TEXTURES");
    return names;
}

} // namespace glint::renderer
