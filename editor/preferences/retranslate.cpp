#include "retranslate.h"

#include <QAbstractButton>
#include <QAction>
#include <QCoreApplication>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QVariant>
#include <QWidget>

#include <array>

namespace glint::editor {
namespace {

// One dynamic property per role; its value is the pair (context, source) of plain pointers to the
// caller's literals, so nothing is copied or freed.
constexpr std::array<const char*, 5> kProperties{"_glint_tr_text", "_glint_tr_title", "_glint_tr_tooltip",
                                                 "_glint_tr_accessible", "_glint_tr_placeholder"};

void apply(QObject* object, TextRole role, const QString& text) {
    auto* widget = qobject_cast<QWidget*>(object);
    auto* action = qobject_cast<QAction*>(object);
    switch (role) {
    case TextRole::Text:
        if (action) action->setText(text);
        else if (auto* label = qobject_cast<QLabel*>(object)) label->setText(text);
        else if (auto* button = qobject_cast<QAbstractButton*>(object)) button->setText(text);
        else if (widget) widget->setWindowTitle(text);
        break;
    case TextRole::Title:
        if (auto* menu = qobject_cast<QMenu*>(object)) menu->setTitle(text);
        else if (auto* box = qobject_cast<QGroupBox*>(object)) box->setTitle(text);
        else if (widget) widget->setWindowTitle(text); // docks and tool bars (their toggle actions follow)
        else if (action) action->setText(text);
        break;
    case TextRole::ToolTip:
        if (action) action->setToolTip(text);
        else if (widget) widget->setToolTip(text);
        break;
    case TextRole::AccessibleName:
        if (widget) widget->setAccessibleName(text);
        break;
    case TextRole::Placeholder:
        if (auto* edit = qobject_cast<QLineEdit*>(object)) edit->setPlaceholderText(text);
        break;
    }
}

void retranslateObject(QObject* object) {
    for (std::size_t role = 0; role < kProperties.size(); ++role) {
        const QVariant kept = object->property(kProperties[role]);
        if (!kept.isValid()) continue;
        const auto source = kept.value<QPair<quintptr, quintptr>>();
        apply(object, static_cast<TextRole>(role),
              QCoreApplication::translate(reinterpret_cast<const char*>(source.first), reinterpret_cast<const char*>(source.second)));
    }
}

} // namespace

void keepTranslated(QObject* object, TextRole role, const char* context, const char* source) {
    const QPair<quintptr, quintptr> kept{reinterpret_cast<quintptr>(context), reinterpret_cast<quintptr>(source)};
    object->setProperty(kProperties[static_cast<std::size_t>(role)], QVariant::fromValue(kept));
    apply(object, role, QCoreApplication::translate(context, source));
}

QString keptText(const QObject* object, TextRole role) {
    const QVariant kept = object->property(kProperties[static_cast<std::size_t>(role)]);
    if (!kept.isValid()) return {};
    const auto source = kept.value<QPair<quintptr, quintptr>>();
    return QCoreApplication::translate(reinterpret_cast<const char*>(source.first), reinterpret_cast<const char*>(source.second));
}

QString countText(const char* context, const char* plural, const char* englishSingular, int n) {
    const QString translated = QCoreApplication::translate(context, plural, nullptr, n);
    const QString untranslated = QString::fromUtf8(plural).replace(QLatin1String("%n"), QString::number(n));
    if (translated != untranslated || n != 1) return translated;
    return QString::fromUtf8(englishSingular).replace(QLatin1String("%n"), QString::number(n));
}

void retranslateTree(QObject* root) {
    retranslateObject(root);
    for (QObject* child : root->findChildren<QObject*>()) retranslateObject(child);
}

} // namespace glint::editor
