#pragma once
// Texts that follow the language while the editor runs (Preferences > Language applies at once).
// keepTranslated() sets a text from its untranslated source and keeps the source and its context
// on the object; retranslateTree() sets every such text under a root again, from the translators
// installed now. Widgets that build their texts from data (forms, models) rebuild instead.
#include <QObject>
#include <QString>

namespace glint::editor {

enum class TextRole { Text, Title, ToolTip, AccessibleName, Placeholder };

// `context` is the class whose tr() the string belongs to (what lupdate records), e.g.
// MainWindow::staticMetaObject.className(); mark `source` for lupdate with QT_TRANSLATE_NOOP or
// QT_TR_NOOP. Both must outlive the object (string literals do).
void keepTranslated(QObject* object, TextRole role, const char* context, const char* source);

// Sets every kept text of `root` and its descendants again (call on QEvent::LanguageChange).
void retranslateTree(QObject* root);

// The kept text of `object` for `role` in the language of the moment, or an empty string when it
// has none. Unlike the object's text it is the one set with keepTranslated: the Undo action's
// "&Undo" while its menu text says "&Undo Rename".
QString keptText(const QObject* object, TextRole role);

// "%n nodes" through the translators' plural forms (`plural`, marked with QT_TRANSLATE_N_NOOP in
// `context`); in English, which has no translator, `englishSingular` ("%n node") when n is 1.
QString countText(const char* context, const char* plural, const char* englishSingular, int n);

} // namespace glint::editor
