#pragma once
// The materials New offers: plain glTF material values (metallic-roughness and the KHR_materials_*
// extensions Glint renders), so a preset is nothing but a starting point that every glTF viewer and
// Blender read the same way.
#include "scene/core/material.h"

#include <QString>

#include <span>

namespace glint::editor {

struct MaterialPreset {
    const char* id;      // stable, for object names and tests ("plastic")
    const char* title;   // English; shown through MaterialPresets::title (translated)
    Material value;      // named after the title
};

std::span<const MaterialPreset> materialPresets();
const MaterialPreset* findMaterialPreset(const QString& id);
QString presetTitle(const MaterialPreset& preset); // translated

} // namespace glint::editor
