#pragma once
// The scene core names its commands in English (it knows no Qt); this translates those labels
// for the history view and the Undo/Redo menu items: fixed labels by table, "Add NAME" style
// labels by their prefix. The editor labels its own edits more precisely than the core can
// ("Rotate", "Change exposure"; LabelledCommand): the describe* functions say, in English (the
// history keeps English and translates when it shows), what an edit from `before` to `after` is.
#include "scene/core/scene.h"

#include <QString>

#include <string>

namespace glint::editor {

QString commandLabel(const std::string& label);

// "Move", "Rotate", "Scale", or "Transform" when more than one part changes.
std::string describeTransformEdit(const Transform& before, const Transform& after);
// "Change exposure", "Change environment image", ...; empty when several parts change.
std::string describeSettingsEdit(const ProjectSettings& before, const ProjectSettings& after);
// "Change light colour", "Change focus distance", "Change radius", ...; empty when unclear.
std::string describeComponentEdit(const Component& before, const Component& after);
// "Change roughness", "Change base colour", ...; empty when several fields change.
std::string describeMaterialEdit(const Material& before, const Material& after);

} // namespace glint::editor
