#pragma once
// The scene's material textures decoded, bucketed and mipmapped for upload (renderer/gpu_scene/
// texture_arrays.h uploads them). A texture array holds images of one size and one colour space, so
// images are grouped by (colour space, width, height): sRGB data (base colour, emission, specular
// colour) goes to GL_SRGB8_ALPHA8 arrays, linear data (metallic-roughness, normals, specular,
// transmission, thickness) to GL_RGBA8 ones. Each bucket
// costs a sampler unit; when a scene has more sizes than units, the smallest bucket of a colour
// space is resampled to the next larger size of that space (with a warning) until it fits.
// CPU only: no GL here.
#include "renderer/gpu_scene/texture_cache.h"
#include "renderer/gpu_scene/texture_mips.h"
#include "scene/core/scene.h"
#include "scene/io/image_decoder.h"

#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace glint::renderer {

struct TextureSlot {
    int bucket = -1; // -1: no texture (the factor alone)
    int layer = 0;
};

struct TextureBucket {
    bool srgb = false;
    int width = 0;
    int height = 0;
    std::vector<std::shared_ptr<const MipChain>> layers; // each a full mip chain down to 1x1 (shared with a TextureCache)
};

struct TextureLimits {
    int maxBuckets = 3;     // sampler units left for texture arrays
    int maxLayers = 256;    // GL_MAX_ARRAY_TEXTURE_LAYERS (GL 4.1 guarantees 2048; 256 keeps uploads bounded)
    int maxSize = 8192;     // GL_MAX_TEXTURE_SIZE; larger images use their first mip level that fits
};

struct TextureSet {
    std::vector<TextureBucket> buckets;
    std::map<std::pair<ImageId, bool>, TextureSlot> slotOf; // (image, sRGB) -> where it lives (not "slots": a Qt macro)
    std::vector<std::string> warnings;
    // (image, sRGB) -> its mean colour in linear light (its 1x1 mip level): the light sampling of
    // emissive textures weighs triangles by it (texture_refs.h, sampledEmission).
    std::map<std::pair<ImageId, bool>, glm::vec3> meanOf;

    TextureSlot find(ImageId image, bool srgb) const;
    bool empty() const { return buckets.empty(); }
};

// Materials that visible mesh primitives use (their alpha and sidedness select shader variants).
std::set<MaterialId> meshMaterials(const Scene& scene);
// Materials whose textures the path tracer samples: those of visible meshes and of visible analytic
// shapes (which have texture coordinates of their own, docs/MATERIALS.md).
std::set<MaterialId> texturedMaterials(const Scene& scene);

// The (image, sRGB) pairs that `materials` sample: when it is unchanged, a material edit needs no
// new texture set (only new material records).
std::set<std::pair<ImageId, bool>> texturesUsed(const Scene& scene, const std::set<MaterialId>& materials);

// Textures that the path tracer samples for `materials` (base colour, metallic-roughness, normal,
// emissive, and the specular, specular colour, transmission and thickness textures; never occlusion). Missing or undecodable images: an 8x8 magenta/black checker for colour data, nothing
// (the factor alone) for linear data, and a warning either way. Throws std::runtime_error when a
// bucket would exceed `limits.maxLayers` or the colour spaces outnumber `limits.maxBuckets`.
// `cache`: decoded and mip-mapped images kept between builds; `decoder` runs only for images it
// does not hold (the set is bit-identical either way).
TextureSet buildTextureSet(const Scene& scene, const std::set<MaterialId>& materials, const ImageDecoder& decoder,
                           const TextureLimits& limits, TextureCache* cache = nullptr);

} // namespace glint::renderer
