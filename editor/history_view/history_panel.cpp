#include "history_panel.h"

#include "history_model.h"

#include "editor/document/document.h"
#include "editor/preferences/retranslate.h"

#include <QEvent>
#include <QListView>
#include <QVBoxLayout>

#include <exception>

namespace glint::editor {

HistoryPanel::HistoryPanel(Document& document, QWidget* parent) : QWidget(parent), document_(document) {
    model_ = new HistoryModel(document_, this);
    view_ = new QListView(this);
    view_->setModel(model_);
    keepTranslated(view_, TextRole::AccessibleName, staticMetaObject.className(), QT_TR_NOOP("Undo history"));
    view_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    view_->setSelectionMode(QAbstractItemView::SingleSelection);
    connect(model_, &HistoryModel::modelReset, this, &HistoryPanel::selectCurrent);
    connect(view_, &QListView::clicked, this, [this](const QModelIndex& index) {
        try {
            document_.jumpTo(static_cast<std::size_t>(index.row()));
        } catch (const std::exception& e) {
            emit message(QString::fromStdString(e.what()));
        }
    });
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addWidget(view_);
    selectCurrent();
}

void HistoryPanel::changeEvent(QEvent* event) {
    QWidget::changeEvent(event);
    // The labels are translated when shown: ask the view to read them again.
    if (event->type() == QEvent::LanguageChange && model_->rowCount() > 0)
        emit model_->dataChanged(model_->index(0), model_->index(model_->rowCount() - 1));
}

void HistoryPanel::selectCurrent() {
    const QModelIndex current = model_->index(model_->currentRow());
    view_->setCurrentIndex(current);
    view_->scrollTo(current);
}

} // namespace glint::editor
