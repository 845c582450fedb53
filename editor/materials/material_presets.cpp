#include "material_presets.h"

#include <QCoreApplication>

#include <vector>

namespace glint::editor {
namespace {

Material dielectric(const char* name, glm::vec3 color, float roughness) {
    Material m;
    m.name = name;
    m.baseColorFactor = glm::vec4(color, 1.0f);
    m.metallicFactor = 0.0f;
    m.roughnessFactor = roughness;
    return m;
}

Material metal(const char* name, glm::vec3 color, float roughness) {
    Material m = dielectric(name, color, roughness);
    m.metallicFactor = 1.0f;
    return m;
}

std::vector<MaterialPreset> makePresets() {
    std::vector<MaterialPreset> presets;
    // Linear factors (glTF stores them linear): 0.8 is a light grey, 0.18 a mid grey.
    presets.push_back({"plastic", QT_TRANSLATE_NOOP("glint::editor::MaterialPresets", "Plastic"),
                       dielectric("Plastic", {0.8f, 0.8f, 0.8f}, 0.4f)});
    presets.push_back({"rough", QT_TRANSLATE_NOOP("glint::editor::MaterialPresets", "Rough"),
                       dielectric("Rough", {0.5f, 0.5f, 0.5f}, 1.0f)});
    // Clear-coat-like: a glossy dielectric (KHR_materials_clearcoat is not rendered; a low roughness
    // with the full specular layer is the nearest plain value).
    presets.push_back({"glossy", QT_TRANSLATE_NOOP("glint::editor::MaterialPresets", "Glossy (clear coat)"),
                       dielectric("Glossy", {0.6f, 0.05f, 0.05f}, 0.05f)});
    // Metals: the base colour is the reflectance at normal incidence (measured values, linear).
    presets.push_back({"metal", QT_TRANSLATE_NOOP("glint::editor::MaterialPresets", "Metal"),
                       metal("Metal", {0.91f, 0.92f, 0.92f}, 0.2f)});
    presets.push_back({"gold", QT_TRANSLATE_NOOP("glint::editor::MaterialPresets", "Gold"),
                       metal("Gold", {1.0f, 0.766f, 0.336f}, 0.15f)});
    presets.push_back({"brushed", QT_TRANSLATE_NOOP("glint::editor::MaterialPresets", "Brushed metal"),
                       metal("Brushed metal", {0.91f, 0.92f, 0.92f}, 0.5f)});
    Material glass = dielectric("Glass", {1.0f, 1.0f, 1.0f}, 0.0f);
    glass.transmissionFactor = 1.0f;
    glass.ior = 1.5f;
    glass.thicknessFactor = 1.0f; // refracts as a solid (KHR_materials_volume)
    presets.push_back({"glass", QT_TRANSLATE_NOOP("glint::editor::MaterialPresets", "Glass"), glass});
    Material frosted = glass;
    frosted.name = "Frosted glass";
    frosted.roughnessFactor = 0.3f;
    presets.push_back({"frosted", QT_TRANSLATE_NOOP("glint::editor::MaterialPresets", "Frosted glass"), frosted});
    Material emitter = dielectric("Emitter", {0.0f, 0.0f, 0.0f}, 1.0f);
    emitter.emissiveFactor = glm::vec3(1.0f);
    emitter.emissiveStrength = 5.0f; // KHR_materials_emissive_strength
    presets.push_back({"emitter", QT_TRANSLATE_NOOP("glint::editor::MaterialPresets", "Emitter"), emitter});
    return presets;
}

} // namespace

std::span<const MaterialPreset> materialPresets() {
    static const std::vector<MaterialPreset> presets = makePresets();
    return presets;
}

const MaterialPreset* findMaterialPreset(const QString& id) {
    for (const MaterialPreset& preset : materialPresets())
        if (id == QLatin1String(preset.id)) return &preset;
    return nullptr;
}

QString presetTitle(const MaterialPreset& preset) {
    return QCoreApplication::translate("glint::editor::MaterialPresets", preset.title);
}

} // namespace glint::editor
