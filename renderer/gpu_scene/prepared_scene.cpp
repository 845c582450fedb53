#include "renderer/gpu_scene/prepared_scene.h"

#include "renderer/gpu_scene/texture_refs.h"
#include "scene/anim/node_animation.h"
#include "scene/anim/scene_at_time.h"
#include "scene/core/portal.h"
#include "scene/io/oiio/oiio_image_decoder.h"

#include <algorithm>

namespace glint::renderer {
namespace {

// Decodes through OpenImageIO and reports each texture to the progress callback before decoding
// it, so a long decode is announced and a superseded preparation stops between two textures.
class ReportingDecoder final : public ImageDecoder {
public:
    ReportingDecoder(const PrepareControl& control, std::size_t total) : control_(control), total_(total) {}
    std::optional<ImageSize> probe(std::span<const std::uint8_t> encoded) const override { return decoder_.probe(encoded); }
    DecodedImage<float> decodeFloat(std::span<const std::uint8_t> encoded, const DecodeLimits& limits) const override {
        report();
        return decoder_.decodeFloat(encoded, limits);
    }
    DecodedImage<std::uint8_t> decode8(std::span<const std::uint8_t> encoded, const DecodeLimits& limits) const override {
        report();
        return decoder_.decode8(encoded, limits);
    }

private:
    void report() const {
        // Decodes can outnumber the textures counted up front (WaterBottle: 5 for 4): never report
        // more than all.
        if (control_.progress) control_.progress(PreparationStage::Textures, std::min(done_, total_), total_);
        ++done_;
    }
    OiioImageDecoder decoder_;
    const PrepareControl& control_;
    std::size_t total_;
    mutable std::size_t done_ = 0; // one decoder per preparation, on one thread
};

// COLOR_0 needs the textured vertex layout even without a texture.
bool meshesHaveColors(const Scene& scene) {
    for (const auto& [id, mesh] : scene.meshes)
        for (const Primitive& p : mesh.primitives)
            if (!p.colors.empty()) return true;
    return false;
}

void report(const PrepareControl& control, PreparationStage stage, std::size_t done, std::size_t total) {
    if (control.progress) control.progress(stage, done, total);
}

Warnings textureWarnings(const std::vector<std::string>& messages) {
    Warnings warnings;
    for (const std::string& message : messages) warnings.push_back({{}, textureWarningCode(message), message});
    return warnings;
}

} // namespace

std::map<std::string, std::string> SceneFeatures::defines() const {
    std::map<std::string, std::string> defines;
    if (meshes) defines["HAS_MESHES"] = "";
    if (shapes) defines["HAS_SHAPES"] = "";
    if (punctualLights) defines["HAS_PUNCTUAL_LIGHTS"] = "";
    if (environmentMap) defines["HAS_ENV_MAP"] = "";
    if (textures) { // meshes or shapes
        defines["HAS_TEXTURES"] = "";
        defines["TEXTURE_ARRAY_COUNT"] = std::to_string(textureArrays);
        for (const std::string& name : extensionTextureDefines(extensionTextures)) defines[name] = "";
    }
    if (meshes && alpha) defines["HAS_ALPHA"] = "";
    if (meshes && singleSided) defines["HAS_SINGLE_SIDED"] = "";
    if (emissiveShapes) defines["HAS_EMISSIVE_SHAPES"] = "";
    if (areaEmitters) defines["HAS_AREA_EMITTERS"] = "";
    if (media) defines["HAS_MEDIA"] = "";
    if (indexMatched) defines["HAS_INDEX_MATCHED"] = "";
    if (portals) defines["HAS_PORTALS"] = "";
    if (transmission) defines["HAS_TRANSMISSION"] = "";
    return defines;
}

void addMeshMaterialFeatures(const Scene& scene, SceneFeatures& features) {
    for (const MaterialId id : meshMaterials(scene)) {
        const Material m = scene.materials.contains(id) ? scene.materials.at(id) : Material{};
        if (m.alphaMode != AlphaMode::Opaque) features.alpha = true;
        if (culledFromBehind(m)) features.singleSided = true;
    }
}

bool usesMedia(const Scene& scene) {
    if (scene.settings.fog.enabled()) return true;
    for (const auto& [id, material] : scene.materials)
        if (scatters(material)) return true;
    return false;
}

bool usesIndexMatched(const Scene& scene) {
    for (const auto& [id, m] : scene.materials)
        if (indexMatched(m)) return true;
    return false;
}

bool usesTransmission(const Scene& scene) {
    for (const auto& [id, m] : scene.materials)
        if (m.transmissionFactor > 0.0f) return true;
    return false;
}

bool hasUnsampledEmitters(const Scene& scene, const TextureSet* textures) {
    const auto emits = [](const Material& m) { return m.emissiveFactor * m.emissiveStrength != glm::vec3(0.0f); };
    for (const MaterialId id : meshMaterials(scene)) {
        const Material* m = scene.materials.find(id);
        if (m && emits(*m) && sampledEmission(scene, *m, textures) == glm::vec3(0.0f)) return true;
    }
    for (const auto& [id, node] : scene.nodes()) {
        const auto* shape = node.get<Shape>();
        const Material* m = shape ? scene.materials.find(shape->material) : nullptr;
        if (m && emits(*m) && (shape->kind == ShapeKind::GroundPlane || hasEmissiveTexture(scene, *m))) return true;
    }
    return false;
}

bool lightSamplingReachesEveryEmitter(const Scene& scene, const TextureSet* textures, bool environmentMap) {
    const Environment& e = scene.settings.environment;
    if (environmentMap || e.color * e.intensity != glm::vec3(0.0f) || hasUnsampledEmitters(scene, textures)) return false;
    for (const auto& [id, node] : scene.nodes())
        if (portalPartner(scene, id)) return false;
    return true;
}

// TextureSet words its warnings for people (texture_set.cpp); the code is read back from them so
// that scripts can filter by a stable name.
std::string textureWarningCode(const std::string& message) {
    if (message.find("resampled") != std::string::npos) return "texture-resampled";
    if (message.find(": missing") != std::string::npos || message.find("names no image") != std::string::npos)
        return "texture-missing";
    return "texture-unreadable";
}

// Steps in the order GpuScene always took them (textures, packing, meshes, environment), so errors
// and bytes are the same as before the split.
PreparedScene prepareScene(const Scene& scene, const std::filesystem::path& environmentFile, const TextureLimits& limits,
                           MeshBvhCache& meshCache, const PrepareControl& control, TextureCache* textureCache) {
    PreparedScene out;
    const std::set<MaterialId> materials = texturedMaterials(scene);
    out.texturesUsed = texturesUsed(scene, materials);
    {
        const ReportingDecoder decoder(control, out.texturesUsed.size());
        out.textures = buildTextureSet(scene, materials, decoder, limits, textureCache);
    }
    report(control, PreparationStage::Textures, out.texturesUsed.size(), out.texturesUsed.size());
    out.warnings = textureWarnings(out.textures.warnings);
    report(control, PreparationStage::Packing, 0, 1);
    out.packed = packScene(scene, &out.textures);
    out.features.shapes = out.packed.shapeCount > 0;
    out.features.punctualLights = out.packed.lightCount > 0;
    out.features.emissiveShapes = out.packed.emissiveShapes;
    out.features.portals = out.packed.portals;
    const bool colors = meshesHaveColors(scene);
    out.meshes = validatedMeshData(scene, out.packed.materialIndex, !out.textures.empty() || colors, meshCache,
                               [&](std::size_t done, std::size_t total) { report(control, PreparationStage::Meshes, done, total); },
                               &out.textures);
    out.features.meshes = !out.meshes.instances.empty() && !out.meshes.flat.trianglePositions.empty();
    out.features.areaEmitters = out.meshes.lights.count() > 0 || out.features.emissiveShapes;
    addMeshMaterialFeatures(scene, out.features);
    out.features.textures = !out.textures.empty() || colors;
    out.features.textureArrays = static_cast<int>(out.textures.buckets.size());
    out.features.extensionTextures = extensionTexturesUsed(scene, materials, out.textures);
    out.environment = scene.settings.environment;
    out.fog = scene.settings.fog;
    out.features.media = usesMedia(scene);
    out.features.indexMatched = usesIndexMatched(scene);
    out.features.transmission = usesTransmission(scene);
    out.environmentFile = environmentFile;
    if (!environmentFile.empty()) {
        report(control, PreparationStage::Environment, 0, 1);
        PreparedEnvironment env{loadEnvironmentImage(environmentFile), {}};
        env.table = twin::buildEnvironmentSamplingTable(env.image.width, env.image.height, env.image.rgb);
        out.environmentMap = std::move(env);
        out.features.environmentMap = true;
    }
    out.features.everyEmitterLightSampled = lightSamplingReachesEveryEmitter(scene, &out.textures, out.features.environmentMap);
    return out;
}


} // namespace glint::renderer
