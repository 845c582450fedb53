#pragma once
// The scene core names its commands in English (it knows no Qt); this translates those labels
// for the history view and the Undo/Redo menu items: fixed labels by table, "Add NAME" style
// labels by their prefix.
#include <QString>

#include <string>

namespace glint::editor {

QString commandLabel(const std::string& label);

} // namespace glint::editor
