#include "preferences.h"

#include <QCoreApplication>
#include <QSettings>

#include <algorithm>

namespace glint::editor {

Preferences Preferences::load() {
    QSettings s;
    Preferences p;
    p.theme = s.value("ui/theme", p.theme).toString();
    p.language = s.value("ui/language", p.language).toString();
    p.autosaveMinutes = s.value("autosave/minutes", p.autosaveMinutes).toInt();
    p.viewportSamples = std::max(0, s.value("viewport/samples", p.viewportSamples).toInt());
    // Before version 2 the dialog stored every action's shortcut, the empty ones of actions that had
    // none too (the gizmo modes among them, which have W/E/R now): only real bindings are kept.
    const bool everything = s.value("ui/keymapVersion", 1).toInt() < 2;
    s.beginGroup("keymap");
    for (const QString& key : s.childKeys()) {
        const QKeySequence sequence(s.value(key).toString());
        if (!(everything && sequence.isEmpty())) p.keymap[key] = sequence;
    }
    s.endGroup();
    return p;
}

void Preferences::save() const {
    QSettings s;
    s.setValue("ui/theme", theme);
    s.setValue("ui/language", language);
    s.setValue("autosave/minutes", autosaveMinutes);
    s.setValue("viewport/samples", viewportSamples);
    s.remove("keymap");
    s.setValue("ui/keymapVersion", 2); // only what differs from the defaults, cleared shortcuts too
    s.beginGroup("keymap");
    for (auto it = keymap.begin(); it != keymap.end(); ++it)
        s.setValue(it.key(), it.value().toString(QKeySequence::PortableText));
    s.endGroup();
}

QList<QPair<QString, QString>> availableLanguages() {
    return {{"system", QCoreApplication::translate("glint::editor::Preferences", "System language")},
            {"en", QStringLiteral("English")},
            {"it", QStringLiteral("Italiano")},
            {"de", QStringLiteral("Deutsch")},
            {"fr", QStringLiteral("Français")},
            {"es", QStringLiteral("Español")}};
}

} // namespace glint::editor
