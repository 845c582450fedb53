#pragma once
// The editor's preferences as stored in QSettings, read and written in one place.
#include <QKeySequence>
#include <QMap>
#include <QString>

namespace glint::editor {

struct Preferences {
    QString theme = QStringLiteral("system");   // system, light, dark
    QString language = QStringLiteral("system"); // system, en, it, de, fr, es
    int autosaveMinutes = 2;                     // 0 = off
    int viewportSamples = 1024;                  // the viewport stops adding samples here; 0 = no cap
    QMap<QString, QKeySequence> keymap;          // action object name -> shortcut (what differs from the defaults)

    static Preferences load();
    void save() const;
};

// The languages the editor ships, as (code, native name); "system" first.
QList<QPair<QString, QString>> availableLanguages();

} // namespace glint::editor
