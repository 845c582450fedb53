#pragma once
// Loads the editor's translations (compiled into the library as :/i18n/glint_<lang>.qm) and Qt's
// own for the chosen language, "system" meaning the system locale.
#include <QString>
#include <QTranslator>

class QCoreApplication;

namespace glint::editor {

class Translations {
public:
    // Returns the language code installed ("en" when nothing was needed or found).
    QString install(QCoreApplication& app, const QString& language);

private:
    QTranslator editor_;
    QTranslator qt_;
};

} // namespace glint::editor
