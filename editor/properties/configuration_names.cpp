#include "configuration_names.h"

#include <QCoreApplication>

namespace glint::editor {
namespace {

struct Entry {
    const char* id;
    const char* title;
};

constexpr Entry kEntries[] = {
    {"baseline", QT_TRANSLATE_NOOP("glint::editor::Configurations", "Baseline")},
    {"realistic", QT_TRANSLATE_NOOP("glint::editor::Configurations", "Realistic")},
    {"full", QT_TRANSLATE_NOOP("glint::editor::Configurations", "Full")},
    {"heavy", QT_TRANSLATE_NOOP("glint::editor::Configurations", "Heavy")},
    {"accumulate", QT_TRANSLATE_NOOP("glint::editor::Configurations", "Accumulate")},
    {"reference", QT_TRANSLATE_NOOP("glint::editor::Configurations", "Reference")},
};
} // namespace

const QStringList& configurationIds() {
    static const QStringList ids = [] {
        QStringList list;
        for (const Entry& e : kEntries) list << QString::fromLatin1(e.id);
        return list;
    }();
    return ids;
}

QString configurationTitle(std::string_view id) {
    for (const Entry& e : kEntries)
        if (id == e.id) return QCoreApplication::translate("glint::editor::Configurations", e.title);
    return QString::fromUtf8(id.data(), qsizetype(id.size()));
}

} // namespace glint::editor
