#pragma once
// A material's texture references as the path tracer reads them: where the image lives (texture
// array bucket and layer), the sampler's wrap and filter modes (applied in the shader, since one
// array holds textures with different samplers), the UV set and the KHR_texture_transform matrix.
// Layout in shaders/textures/texture_refs.glsl. CPU only: no GL here.
#include "renderer/gpu_scene/texture_set.h"

#include <glm/glm.hpp>

#include <set>
#include <string>
#include <vector>

namespace glint::renderer {

inline constexpr int textureRefTexels = 3;
// Order of the references in a material record (TEXREF_* in the shader).
enum TextureRefIndex {
    baseColorRef = 0, metallicRoughnessRef = 1, normalRef = 2, emissiveRef = 3,
    specularRef = 4, specularColorRef = 5, transmissionRef = 6, thicknessRef = 7, // KHR_materials_* textures
    textureRefCount = 8
};

// Textures of the KHR_materials_* extensions that a scene samples, each a shader variant of its
// own (HAS_SPECULAR_TEXTURES, HAS_TRANSMISSION_TEXTURES, HAS_THICKNESS_TEXTURES): a scene without
// them runs no code for them.
enum ExtensionTextureBits : unsigned { specularTextureBit = 1u, transmissionTextureBit = 2u, thicknessTextureBit = 4u };

// Flags texel value: wrapS + 3 wrapT (0 repeat, 1 clamp, 2 mirrored repeat) + 9 nearest magnification
// + 18 nearest minification + 36 mipmapped minification.
float samplerFlags(const Sampler& sampler);

// Three texels: (bucket or -1, layer, flags, texCoord); (a, b, c, d); (tx, ty, scale, 0) with
// uv' = (a u + b v + tx, c u + d v + ty) = offset + rotation * scale * uv (the extension's order).
// The last 0 is the emissive reference's light luminance in a material record (packMaterial).
void appendTextureRef(std::vector<glm::vec4>& out, const TextureRef& ref, TextureSlot slot, const Sampler& sampler);

// The references of `m` in TextureRefIndex order (colour space per slot: sRGB for base colour,
// emission and specular colour). Without a texture set every reference is empty.
void appendMaterialTextureRefs(std::vector<glm::vec4>& out, const Scene* scene, const Material& m, const TextureSet* textures);

// Emission that light sampling assumes for `m`, which weighs each emissive triangle by its area
// times this luminance: its factors, times its emissive texture's mean colour where it has one
// (TextureSet::meanOf; none without `textures`). A textured emitter's light samples then carry the
// texel's emission at the sampled point (shaders/pathtrace/emissive_lights.glsl), so the estimate
// stays unbiased whatever the texture's layout.
glm::vec3 sampledEmission(const Scene& scene, const Material& m, const TextureSet* textures);

// Whether `m`'s emission is modulated by a texture.
bool hasEmissiveTexture(const Scene& scene, const Material& m);

// ExtensionTextureBits of the textures that `materials` sample and `textures` holds.
unsigned extensionTexturesUsed(const Scene& scene, const std::set<MaterialId>& materials, const TextureSet& textures);

// The shader defines of an ExtensionTextureBits mask.
std::vector<std::string> extensionTextureDefines(unsigned mask);

} // namespace glint::renderer
