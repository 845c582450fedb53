#pragma once
// The CPU stage of a GPU scene: everything GpuScene uploads, computed without GL, so the editor can
// run it on a worker thread while the viewport keeps drawing. Mesh BVHs (through a MeshBvhCache),
// the top level, texture decoding and mipmaps, the environment's sampling table and the packed
// buffers. Deterministic: the same scene gives the same bytes on any thread, and GpuScene's one-step
// constructor is this plus the upload, so both paths upload identical data.
// Thread safety: prepareScene reads only its arguments; the MeshBvhCache must not be used by two
// preparations at once (the editor runs them one after another on one worker).
#include "renderer/cpu_twin/env_sampling.h"
#include "renderer/gpu_scene/environment_image.h"
#include "renderer/gpu_scene/mesh_data.h"
#include "renderer/gpu_scene/packed_scene.h"
#include "renderer/gpu_scene/texture_set.h"
#include "scene/core/diagnostics.h"
#include "scene/core/scene.h"

#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>

namespace glint::renderer {

// What a scene uses, each a shader variant define: a scene pays only for what it has. That matters
// most on llvmpipe, which runs every branch of the shader for all pixels (masked), and a loop's body
// at least once even where it has nothing to do (docs/PERFORMANCE.md, "Every branch costs").
struct SceneFeatures {
    bool meshes = false;
    bool shapes = false;         // an analytic shape, area light or portal (HAS_SHAPES)
    bool punctualLights = false; // a point, spot or sun light (HAS_PUNCTUAL_LIGHTS)
    bool environmentMap = false;
    bool textures = false;    // material textures or COLOR_0 on meshes: UVs, tangents, texture arrays
    int textureArrays = 0;    // texture arrays bound (TEXTURE_ARRAY_COUNT)
    unsigned extensionTextures = 0; // KHR_materials_* textures sampled (texture_refs.h ExtensionTextureBits)
    bool alpha = false;       // a mesh material with alpha mode MASK or BLEND
    bool singleSided = false; // a non-emissive single-sided mesh material: camera rays cull its back faces
    bool emissiveShapes = false; // an emissive shape or an area light: light-sampled (HAS_EMISSIVE_SHAPES)
    bool areaEmitters = false;   // the above or an emissive triangle: the area light sample (HAS_AREA_EMITTERS)
    bool media = false;       // fog, or a material whose volume scatters (HAS_MEDIA)
    bool indexMatched = false; // a transmissive IOR-1 material: shadow rays cross it (HAS_INDEX_MATCHED)
    bool portals = false;     // a linked portal pair: paths cross it (HAS_PORTALS)
    bool transmission = false; // a material that transmits: the BSDF's glass lobe (HAS_TRANSMISSION)
    // Light sampling reaches every emitter (lightSamplingReachesEveryEmitter): paths may end at their
    // last vertex's light samples. A uniform, not a define.
    bool everyEmitterLightSampled = false;
    std::map<std::string, std::string> defines() const; // gl::Defines: NAME -> value
};

// Adds the alpha and sidedness features of the visible meshes' materials.
void addMeshMaterialFeatures(const Scene& scene, SceneFeatures& features);
// Whether the scene has fog or a material whose volume scatters.
bool usesMedia(const Scene& scene);
// Whether a material is index-matched (packed_scene.h indexMatched): paths and shadow rays cross it.
bool usesIndexMatched(const Scene& scene);
// Whether a material transmits light (KHR_materials_transmission factor above 0).
bool usesTransmission(const Scene& scene);
// Whether an emitter is left out of light sampling, so that only BSDF-sampled rays find it: an
// emissive ground plane or emissive-textured shape (packed_scene.cpp), or an emissive mesh material
// whose texture has no mean in `textures` (texture_refs.h, sampledEmission).
bool hasUnsampledEmitters(const Scene& scene, const TextureSet* textures);
// Whether light sampling reaches every emitter a ray can meet: no environment map (`environmentMap`)
// and a black background colour, no portal (paths cross it, shadow rays do not), and no emitter left
// to BSDF-sampled rays (hasUnsampledEmitters). Then a path may end at its last vertex's light samples.
bool lightSamplingReachesEveryEmitter(const Scene& scene, const TextureSet* textures, bool environmentMap);

struct PreparedEnvironment {
    EnvironmentImage image;
    twin::EnvironmentSamplingTable table;
};

struct PreparedScene {
    SceneFeatures features;
    PackedScene packed;
    MeshData meshes;
    TextureSet textures;
    std::set<std::pair<ImageId, bool>> texturesUsed;
    Environment environment;
    Fog fog;
    std::optional<PreparedEnvironment> environmentMap;
    std::filesystem::path environmentFile;
    // Problems that did not stop the preparation, naming the texture (code texture-missing,
    // texture-unreadable, texture-resampled). `file` is empty: the host names the scene file.
    Warnings warnings;
};

// The steps of a preparation, in the order they run (Picking is the editor's, after prepareScene).
enum class PreparationStage { Textures, Packing, Meshes, Environment, Picking };

// Reports where a preparation is. A callback may throw (PreparationCancelled) to stop the
// preparation between two steps.
struct PrepareControl {
    std::function<void(PreparationStage stage, std::size_t done, std::size_t total)> progress;
};

// Thrown out of prepareScene by a progress callback when a newer preparation supersedes it.
struct PreparationCancelled {};

// `scene`: already posed at the time to render (renderer/scene_snapshot.h). `limits`: the GL context's texture
// limits (queryTextureLimits, read on the GL thread). Throws std::runtime_error or FileError like
// GpuScene does, and whatever `control.progress` throws. `textureCache`: decoded, mip-mapped images
// kept between preparations (texture_cache.h; it locks itself); none: every image is decoded.
PreparedScene prepareScene(const Scene& scene, const std::filesystem::path& environmentFile, const TextureLimits& limits,
                           MeshBvhCache& meshCache, const PrepareControl& control = {}, TextureCache* textureCache = nullptr);


// The warning code of one of TextureSet's messages.
std::string textureWarningCode(const std::string& message);

} // namespace glint::renderer
