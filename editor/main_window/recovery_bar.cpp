#include "recovery_bar.h"

#include "editor/preferences/retranslate.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QStyle>
#include <QToolButton>

namespace glint::editor {

RecoveryBar::RecoveryBar(QWidget* parent) : QFrame(parent) {
    setFrameShape(QFrame::StyledPanel);
    setAutoFillBackground(true);
    QPalette colours = palette();
    colours.setColor(QPalette::Window, QColor(0xff, 0xf1, 0xc4)); // a note, not an error
    colours.setColor(QPalette::WindowText, QColor(0x30, 0x28, 0x10));
    setPalette(colours);
    keepTranslated(this, TextRole::AccessibleName, staticMetaObject.className(), QT_TR_NOOP("Recover unsaved work"));
    auto* icon = new QLabel(this);
    icon->setPixmap(style()->standardIcon(QStyle::SP_MessageBoxInformation).pixmap(20, 20));
    label_ = new QLabel(this);
    label_->setWordWrap(true);
    label_->setTextFormat(Qt::PlainText);
    recover_ = new QPushButton(this);
    keepTranslated(recover_, TextRole::Text, staticMetaObject.className(), QT_TR_NOOP("Recover"));
    discard_ = new QPushButton(this);
    keepTranslated(discard_, TextRole::Text, staticMetaObject.className(), QT_TR_NOOP("Discard"));
    keepTranslated(discard_, TextRole::ToolTip, staticMetaObject.className(), QT_TR_NOOP("Delete the autosaved copy"));
    auto* later = new QToolButton(this);
    later->setAutoRaise(true);
    later->setIcon(style()->standardIcon(QStyle::SP_TitleBarCloseButton));
    keepTranslated(later, TextRole::ToolTip, staticMetaObject.className(), QT_TR_NOOP("Later (File > Recover keeps it)"));
    keepTranslated(later, TextRole::AccessibleName, staticMetaObject.className(), QT_TR_NOOP("Hide"));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(8, 4, 4, 4);
    layout->addWidget(icon);
    layout->addWidget(label_, 1);
    layout->addWidget(recover_);
    layout->addWidget(discard_);
    layout->addWidget(later);
    connect(recover_, &QPushButton::clicked, this, &RecoveryBar::recoverClicked);
    connect(discard_, &QPushButton::clicked, this, &RecoveryBar::discardClicked);
    connect(later, &QToolButton::clicked, this, [this] {
        hide();
        emit dismissed();
    });
    hide();
}

void RecoveryBar::setText(const QString& text) { label_->setText(text); }
QString RecoveryBar::text() const { return label_->text(); }

} // namespace glint::editor
