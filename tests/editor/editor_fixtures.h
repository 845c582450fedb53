#pragma once
// Shared helpers of the editor tests: the bundled sample scene and small look-ups.
#include "editor/document/document.h"

#include <QString>
#include <QTest>

namespace glint::editor::test {

inline QString cornellBox() { return QStringLiteral(GLINT_RESOURCES_DIR "/scenes/cornell_box/cornell_box.gltf"); }

inline NodeId nodeNamed(const Document& document, const std::string& name) {
    auto found = document.scene().findByName(name);
    return found ? *found : NodeId{};
}

} // namespace glint::editor::test
