#pragma once
// A material's texture references as the path tracer reads them: where the image lives (texture
// array bucket and layer), the sampler's wrap and filter modes (applied in the shader, since one
// array holds textures with different samplers), the UV set and the KHR_texture_transform matrix.
// Layout in shaders/textures/texture_refs.glsl. CPU only: no GL here.
#include "renderer/gpu_scene/texture_set.h"

#include <glm/glm.hpp>

#include <vector>

namespace glint::renderer {

inline constexpr int textureRefTexels = 3;
// Order of the references in a material record (TEXREF_* in the shader).
enum TextureRefIndex { baseColorRef = 0, metallicRoughnessRef = 1, normalRef = 2, emissiveRef = 3, textureRefCount = 4 };

// Flags texel value: wrapS + 3 wrapT (0 repeat, 1 clamp, 2 mirrored repeat) + 9 nearest magnification
// + 18 nearest minification + 36 mipmapped minification.
float samplerFlags(const Sampler& sampler);

// Three texels: (bucket or -1, layer, flags, texCoord); (a, b, c, d); (tx, ty, scale, 0) with
// uv' = (a u + b v + tx, c u + d v + ty) = offset + rotation * scale * uv (the extension's order).
void appendTextureRef(std::vector<glm::vec4>& out, const TextureRef& ref, TextureSlot slot, const Sampler& sampler);

// The references of `m` in TextureRefIndex order (colour space per slot: sRGB for base colour and
// emission). Without a texture set every reference is empty.
void appendMaterialTextureRefs(std::vector<glm::vec4>& out, const Scene* scene, const Material& m, const TextureSet* textures);

} // namespace glint::renderer
