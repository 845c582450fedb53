#include "log_panel.h"

#include "editor/preferences/retranslate.h"
#include <QApplication>
#include <QHBoxLayout>
#include <QListWidget>
#include <QPushButton>
#include <QStyle>
#include <QTime>
#include <QVBoxLayout>

namespace glint::editor {

LogPanel::LogPanel(QWidget* parent) : QWidget(parent) {
    list_ = new QListWidget(this);
    keepTranslated(list_, TextRole::AccessibleName, staticMetaObject.className(), QT_TR_NOOP("Log messages"));
    list_->setSelectionMode(QAbstractItemView::ExtendedSelection);
    auto* clearButton = new QPushButton(this);
    keepTranslated(clearButton, TextRole::Text, staticMetaObject.className(), QT_TR_NOOP("Clear"));
    keepTranslated(clearButton, TextRole::AccessibleName, staticMetaObject.className(), QT_TR_NOOP("Clear the log"));
    connect(clearButton, &QPushButton::clicked, this, &LogPanel::clear);

    auto* buttons = new QHBoxLayout;
    buttons->addStretch();
    buttons->addWidget(clearButton);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addWidget(list_);
    layout->addLayout(buttons);
}

int LogPanel::count() const { return list_->count(); }

QString LogPanel::line(int row) const { return list_->item(row)->text(); }

void LogPanel::append(Level level, const QString& text) {
    QStyle::StandardPixmap icon = QStyle::SP_MessageBoxInformation;
    QString prefix = tr("info");
    if (level == Level::Warning) {
        icon = QStyle::SP_MessageBoxWarning;
        prefix = tr("warning");
    } else if (level == Level::Error) {
        icon = QStyle::SP_MessageBoxCritical;
        prefix = tr("error");
    }
    const QString stamped = QStringLiteral("%1 %2: %3").arg(QTime::currentTime().toString("HH:mm:ss"), prefix, text);
    auto* item = new QListWidgetItem(style()->standardIcon(icon), stamped, list_);
    list_->scrollToItem(item);
    if (level != Level::Info) emit problemLogged(text);
}

void LogPanel::warnings(const QStringList& lines) {
    for (const QString& line : lines) warning(line);
}

void LogPanel::clear() { list_->clear(); }

} // namespace glint::editor
