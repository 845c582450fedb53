#include "command_labels.h"

#include <QCoreApplication>

#include <initializer_list>

namespace glint::editor {
namespace {

constexpr const char* kContext = "glint::editor::CommandLabels";

// Labels the scene core uses as they are (scene/history), listed so lupdate finds them.
constexpr const char* kFixed[] = {
    QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Rename"),
    QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Move"),
    QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Show/hide"),
    QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Edit component"),
    QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Reparent"),
    QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Edit settings"),
    QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Remove"),
    QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Delete"),
    QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Duplicate"),
    QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Add camera key"),
    QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Edit camera key"),
    QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Move camera key"),
    QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Remove camera key"),
    QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Camera path mode"),
    QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "mesh"),
    QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "material"),
    QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "texture"),
    QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "image"),
    QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "sampler"),
};

struct Prefix {
    const char* english;
    const char* pattern;
};
constexpr Prefix kPrefixes[] = {
    {"Add ", QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Add %1")},
    {"Remove ", QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Remove %1")},
    {"Duplicate ", QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Duplicate %1")},
    {"Edit ", QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Edit %1")},
    {"Import ", QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Import %1")},
};

QString translated(const char* text) { return QCoreApplication::translate(kContext, text); }

bool isFixed(const std::string& label) {
    for (const char* fixed : kFixed)
        if (label == fixed) return true;
    return false;
}

} // namespace

QString commandLabel(const std::string& label) {
    if (isFixed(label)) return translated(label.c_str());
    // The editor's own labels (below) are sources in this context.
    if (const QString own = translated(label.c_str()); own != QString::fromStdString(label)) return own;
    for (const Prefix& prefix : kPrefixes) {
        const std::string start = prefix.english;
        if (label.rfind(start, 0) != 0) continue;
        const std::string rest = label.substr(start.size());
        // The rest is an asset kind (translated) or a node or file name (kept as it is).
        const QString object = isFixed(rest) ? translated(rest.c_str()) : QString::fromStdString(rest);
        return translated(prefix.pattern).arg(object);
    }
    return QString::fromStdString(label);
}

namespace {

// The first label whose part differs, when exactly one differs; empty otherwise.
struct Part {
    bool differs;
    const char* label;
};

std::string onlyChange(std::initializer_list<Part> parts) {
    const char* found = nullptr;
    for (const Part& part : parts) {
        if (!part.differs) continue;
        if (found && std::string(found) != part.label) return {};
        found = part.label;
    }
    return found ? found : std::string();
}

} // namespace

std::string describeTransformEdit(const Transform& before, const Transform& after) {
    const std::string one = onlyChange({{before.translation != after.translation, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Move")},
                                        {before.rotation != after.rotation, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Rotate")},
                                        {before.scale != after.scale, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Scale")}});
    return one.empty() ? QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Transform") : one;
}

std::string describeSettingsEdit(const ProjectSettings& b, const ProjectSettings& a) {
    const RenderSettings& rb = b.render;
    const RenderSettings& ra = a.render;
    return onlyChange({
        {rb.configuration != ra.configuration, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change configuration")},
        {rb.width != ra.width || rb.height != ra.height, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change image size")},
        {rb.spp != ra.spp, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change samples per pixel")},
        {rb.bounces != ra.bounces, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change bounces")},
        {rb.seed != ra.seed, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change seed")},
        {rb.exposure != ra.exposure, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change exposure")},
        {rb.tonemapper != ra.tonemapper, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change tonemapper")},
        {rb.clamp != ra.clamp, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change radiance clamp")},
        {rb.shutter != ra.shutter, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change motion blur")},
        {rb.sampleBlock != ra.sampleBlock, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change sample blocks")},
        {rb.taa != ra.taa, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change TAA settings")},
        {rb.svgf != ra.svgf, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change SVGF settings")},
        {rb.bloom != ra.bloom, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change bloom")},
        {rb.adaptive != ra.adaptive, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change adaptive sampling")},
        {b.environment.file != a.environment.file, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change environment image")},
        {b.environment.color != a.environment.color, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change environment colour")},
        {b.environment.intensity != a.environment.intensity, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change environment intensity")},
        {b.environment.rotationDegrees != a.environment.rotationDegrees, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Rotate environment")},
        {b.fog != a.fog, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change fog")},
        {b.activeCamera != a.activeCamera, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change active camera")},
        {b.timeline.start != a.timeline.start || b.timeline.end != a.timeline.end, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change timeline range")},
        {b.timeline.fpsNumerator != a.timeline.fpsNumerator || b.timeline.fpsDenominator != a.timeline.fpsDenominator,
         QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change frame rate")},
        {b.output != a.output, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change output")},
        {b.lightUnits != a.lightUnits, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change light units")},
    });
}

std::string describeComponentEdit(const Component& before, const Component& after) {
    if (before.index() != after.index()) return {};
    if (const auto* b = std::get_if<Light>(&before)) {
        const Light& a = std::get<Light>(after);
        return onlyChange({{b->type != a.type, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change light type")},
                           {b->color != a.color, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change light colour")},
                           {b->intensity != a.intensity, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change light intensity")},
                           {b->range != a.range, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change light range")},
                           {b->radius != a.radius, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change light radius")},
                           {b->innerConeAngle != a.innerConeAngle || b->outerConeAngle != a.outerConeAngle,
                            QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change spot cone")},
                           {b->angularDiameter != a.angularDiameter, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change sun size")}});
    }
    if (const auto* b = std::get_if<Camera>(&before)) {
        const Camera& a = std::get<Camera>(after);
        return onlyChange({{b->projection != a.projection, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change projection")},
                           {b->yfov != a.yfov || b->ymag != a.ymag || b->xmag != a.xmag,
                            QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change field of view")},
                           {b->lensRadius != a.lensRadius, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change aperture")},
                           {b->focusDistance != a.focusDistance, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change focus distance")},
                           {b->exposure != a.exposure, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change exposure")},
                           {b->znear != a.znear || b->zfar != a.zfar, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change clipping")},
                           {b->aspectRatio != a.aspectRatio, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change aspect ratio")}});
    }
    if (const auto* b = std::get_if<Shape>(&before)) {
        const Shape& a = std::get<Shape>(after);
        return onlyChange({{b->kind != a.kind, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change shape")},
                           {b->radius != a.radius, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change radius")},
                           {b->height != a.height, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change height")},
                           {b->size != a.size, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change size")},
                           {b->material != a.material, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change material")}});
    }
    return {};
}

std::string describeMaterialEdit(const Material& b, const Material& a) {
    const bool textures = b.baseColorTexture != a.baseColorTexture || b.metallicRoughnessTexture != a.metallicRoughnessTexture ||
                          b.normalTexture != a.normalTexture || b.occlusionTexture != a.occlusionTexture ||
                          b.emissiveTexture != a.emissiveTexture || b.specularTexture != a.specularTexture ||
                          b.specularColorTexture != a.specularColorTexture || b.transmissionTexture != a.transmissionTexture ||
                          b.thicknessTexture != a.thicknessTexture;
    return onlyChange({
        {glm::vec3(b.baseColorFactor) != glm::vec3(a.baseColorFactor), QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change base colour")},
        {b.baseColorFactor.w != a.baseColorFactor.w, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change opacity")},
        {b.metallicFactor != a.metallicFactor, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change metallic")},
        {b.roughnessFactor != a.roughnessFactor, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change roughness")},
        {b.emissiveFactor != a.emissiveFactor, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change emission")},
        {b.emissiveStrength != a.emissiveStrength, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change emission strength")},
        {b.specularFactor != a.specularFactor || b.specularColorFactor != a.specularColorFactor,
         QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change specular")},
        {b.transmissionFactor != a.transmissionFactor, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change transmission")},
        {b.ior != a.ior, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change index of refraction")},
        {b.thicknessFactor != a.thicknessFactor || b.attenuationDistance != a.attenuationDistance || b.attenuationColor != a.attenuationColor ||
             b.scatterColor != a.scatterColor || b.scatterAnisotropy != a.scatterAnisotropy,
         QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change volume")},
        {b.alphaMode != a.alphaMode || b.alphaCutoff != a.alphaCutoff, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change alpha mode")},
        {b.doubleSided != a.doubleSided, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change double sided")},
        {textures, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Change texture")},
        {b.name != a.name, QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Rename material")},
    });
}

} // namespace glint::editor
