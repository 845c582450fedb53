#pragma once
// Shared helpers of the editor tests: the bundled sample scene and small look-ups.
#include "editor/document/document.h"

#include <QAction>
#include <QMenu>
#include <QString>
#include <QTest>
#include <QWidget>

namespace glint::editor::test {

inline QString cornellBox() { return QStringLiteral(GLINT_RESOURCES_DIR "/scenes/cornell_box/cornell_box.gltf"); }

inline NodeId nodeNamed(const Document& document, const std::string& name) {
    auto found = document.scene().findByName(name);
    return found ? *found : NodeId{};
}

// The panel's field of type T by its accessible name (what screen readers announce), or null.
template <class T>
T* fieldNamed(QWidget& panel, const QString& name) {
    for (T* field : panel.findChildren<T*>())
        if (field->accessibleName() == name) return field;
    return nullptr;
}

// The action of `menu` or of its submenus whose text is `text`, or null.
inline QAction* actionNamed(QMenu* menu, const QString& text) {
    for (QAction* action : menu->actions()) {
        if (action->text() == text) return action;
        if (action->menu())
            if (QAction* found = actionNamed(action->menu(), text)) return found;
    }
    return nullptr;
}

} // namespace glint::editor::test
