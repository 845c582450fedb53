#include "history_panel.h"

#include "history_model.h"

#include "editor/document/document.h"

#include <QListView>
#include <QVBoxLayout>

#include <exception>

namespace glint::editor {

HistoryPanel::HistoryPanel(Document& document, QWidget* parent) : QWidget(parent), document_(document) {
    model_ = new HistoryModel(document_, this);
    view_ = new QListView(this);
    view_->setModel(model_);
    view_->setAccessibleName(tr("Undo history"));
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

void HistoryPanel::selectCurrent() {
    const QModelIndex current = model_->index(model_->currentRow());
    view_->setCurrentIndex(current);
    view_->scrollTo(current);
}

} // namespace glint::editor
