#pragma once
// One undo step for several pushes: `body` runs inside a macro of the document's history; an
// exception from it closes the macro and comes back as a message for people (empty: success).
#include "editor/document/document.h"

#include <QString>

#include <exception>

namespace glint::editor {

template <class Body>
QString inMacro(Document& document, const QString& label, Body body) {
    document.beginMacro(label);
    try {
        body();
    } catch (const std::exception& e) {
        document.endMacro();
        return QString::fromStdString(e.what());
    }
    document.endMacro();
    return {};
}

} // namespace glint::editor
