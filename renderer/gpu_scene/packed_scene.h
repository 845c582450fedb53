#pragma once
// The scene flattened into the arrays the path-trace shader reads (layouts in
// shaders/pathtrace/scene_buffers.glsl, lights.glsl, material.glsl). CPU only: no GL here, so the
// packing is tested without a context.
#include "renderer/gpu_scene/texture_set.h"
#include "scene/core/scene.h"

#include <glm/glm.hpp>

#include <map>
#include <vector>

namespace glint::renderer {

// Shape texels: kind, material, id, height; localFromWorld (3 rows); radius, size; emitter (power,
// cumulative power, portal partner's shape index + 1 or 0, |det worldFromLocal|); worldFromLocal (3 rows). Layout: shaders/pathtrace/shapes.glsl.
inline constexpr int shapeTexels = 9;
inline constexpr int materialBaseTexels = 7; // factors, alpha mode and sidedness, then volume scattering
inline constexpr int materialTexels = 31;    // base texels + 8 texture references of 3 texels (texture_refs.h)
inline constexpr int lightTexels = 4;

struct PackedScene {
    std::vector<glm::vec4> shapes;    // shapeTexels per shape
    std::vector<glm::vec4> materials; // materialTexels per material; index 0 is glTF's default material
    std::vector<glm::vec4> lights;    // lightTexels per light
    int shapeCount = 0;
    int lightCount = 0;
    bool sphereLamps = false; // a point or spot light with a radius: rays hit it (HAS_SPHERE_LAMPS)
    // Emissive shapes and area lights (packed as shapes with a material of their own, after the
    // scene's materials): light-sampled in proportion to their power, luminance x world area
    // (HAS_EMISSIVE_SHAPES). An area light is an emitter even at 0 W, so that editing its power
    // keeps the shader variant.
    bool emissiveShapes = false;
    bool portals = false; // a linked portal pair (scene/core/portal.h): rays cross it (HAS_PORTALS)
    float shapeEmitterPower = 0.0f; // the sum of the shapes' powers
    int sceneMaterialCount = 0;     // material records of the scene's materials (+ the default); area lights' follow
    std::map<MaterialId, int> materialIndex;
};

// Visible shapes and lights of `scene` (world transforms resolved), and every material; texture
// references point into `textures` (none without it).
PackedScene packScene(const Scene& scene, const TextureSet* textures = nullptr);

// Whether the material's volume scatters light (GLINT_materials_volume_scatter on an attenuating
// KHR_materials_volume): scenes with one compile the medium code (HAS_MEDIA).
bool scatters(const Material& m);
// Whether paths and shadow rays cross the material's surfaces without a vertex (HAS_INDEX_MATCHED,
// docs/MEDIA.md): transmission 1, IOR 1, not metallic, not emitting, opaque, and no texture that
// could change that or its tint across the surface.
bool indexMatched(const Material& m);

// One material record; texture references are empty unless `scene` and `textures` are given.
std::vector<glm::vec4> packMaterial(const Material& material, const Scene* scene = nullptr, const TextureSet* textures = nullptr);

} // namespace glint::renderer
