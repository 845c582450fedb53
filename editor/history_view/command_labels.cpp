#include "command_labels.h"

#include <QCoreApplication>

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

} // namespace glint::editor
