#pragma once
// Fusion with a Light, Dark or System palette. Qt 6.4 cannot ask the platform for its colour
// scheme (QStyleHints::colorScheme is 6.5+), so System is the palette the platform gave the
// application at start, kept by the caller.
#include <QPalette>
#include <QString>

class QApplication;

namespace glint::editor {

enum class Theme { System, Light, Dark };

Theme themeFromName(const QString& name); // "light", "dark", anything else: System
QString themeName(Theme theme);
void applyTheme(QApplication& app, Theme theme, const QPalette& systemPalette);
QPalette darkPalette();

} // namespace glint::editor
