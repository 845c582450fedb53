#include "language.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>

namespace glint::editor {

Translations& Translations::of(QCoreApplication& app) {
    auto* translations = app.findChild<Translations*>(QString(), Qt::FindDirectChildrenOnly);
    return translations ? *translations : *new Translations(&app);
}

QString Translations::install(QCoreApplication& app, const QString& language) {
    QCoreApplication::removeTranslator(&editor_);
    QCoreApplication::removeTranslator(&qt_);
    const QLocale locale = language == QLatin1String("system") ? QLocale::system() : QLocale(language);
    const QString code = QLocale::languageToCode(locale.language());
    if (code == QLatin1String("en") || !editor_.load(QStringLiteral(":/i18n/glint_%1.qm").arg(code))) return "en";
    app.installTranslator(&editor_);
    if (qt_.load(QStringLiteral("qtbase_%1").arg(code), QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        app.installTranslator(&qt_);
    return code;
}

} // namespace glint::editor
