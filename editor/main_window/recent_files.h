#pragma once
// The most recently opened files, newest first, kept in QSettings.
#include <QStringList>

namespace glint::editor {

class RecentFiles {
public:
    static constexpr int kMaximum = 10;
    QStringList list() const;              // existing files only
    void add(const QString& path);         // moves it to the front
    void remove(const QString& path);
    void clear();
};

} // namespace glint::editor
