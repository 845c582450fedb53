#pragma once
// Loads the editor's translations (compiled into the library as :/i18n/glint_<lang>.qm) and Qt's
// own for the chosen language, "system" meaning the system locale. Installing another language
// while the editor runs sends QEvent::LanguageChange to every widget: the UI follows at once
// (retranslate.h).
#include <QObject>
#include <QString>
#include <QTranslator>

class QCoreApplication;

namespace glint::editor {

class Translations : public QObject {
    Q_OBJECT
public:
    explicit Translations(QObject* parent = nullptr) : QObject(parent) {}
    // Returns the language code installed ("en" when nothing was needed or found).
    QString install(QCoreApplication& app, const QString& language);
    // The application's one set, a child of `app` (made on first use), so the preferences can
    // replace the language the editor started with.
    static Translations& of(QCoreApplication& app);

private:
    QTranslator editor_;
    QTranslator qt_;
};

} // namespace glint::editor
