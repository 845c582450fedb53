#include "recent_files.h"

#include <QFileInfo>
#include <QSettings>

namespace glint::editor {
namespace {
const char* kKey = "files/recent";
}

QStringList RecentFiles::list() const {
    QStringList out;
    for (const QString& path : QSettings().value(kKey).toStringList())
        if (QFileInfo::exists(path)) out << path;
    return out;
}

void RecentFiles::add(const QString& path) {
    QStringList files = QSettings().value(kKey).toStringList();
    const QString absolute = QFileInfo(path).absoluteFilePath();
    files.removeAll(absolute);
    files.prepend(absolute);
    while (files.size() > kMaximum) files.removeLast();
    QSettings().setValue(kKey, files);
}

void RecentFiles::remove(const QString& path) {
    QStringList files = QSettings().value(kKey).toStringList();
    files.removeAll(path);
    QSettings().setValue(kKey, files);
}

void RecentFiles::clear() { QSettings().remove(kKey); }

} // namespace glint::editor
