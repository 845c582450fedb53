#include "history_model.h"

#include "command_labels.h"

#include "editor/document/document.h"

#include <QFont>
#include <QTimer>

namespace glint::editor {

HistoryModel::HistoryModel(Document& document, QObject* parent) : QAbstractListModel(parent), document_(document) {
    // The history calls index listeners from inside push/undo; the model resets afterwards.
    listener_ = document_.history().addIndexListener([this](std::size_t) {
        QMetaObject::invokeMethod(this, &HistoryModel::refresh, Qt::QueuedConnection);
    });
    connect(&document_, &Document::fileChanged, this, &HistoryModel::refresh);
}

HistoryModel::~HistoryModel() { document_.history().removeListener(listener_); }

int HistoryModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(document_.history().count()) + 1;
}

QVariant HistoryModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= rowCount()) return {};
    const History& history = document_.history();
    const auto row = static_cast<std::size_t>(index.row());
    switch (role) {
    case Qt::DisplayRole:
    case Qt::AccessibleTextRole: {
        QString text = row == 0 ? tr("<empty>") : commandLabel(history.label(row - 1));
        if (history.cleanIndex() == row) text += tr(" (saved)");
        return text;
    }
    case Qt::FontRole: {
        QFont font;
        font.setBold(row == history.index());
        font.setItalic(row > history.index()); // undone: redo brings it back
        return font;
    }
    default: return {};
    }
}

int HistoryModel::currentRow() const { return static_cast<int>(document_.history().index()); }

void HistoryModel::refresh() {
    beginResetModel();
    endResetModel();
}

} // namespace glint::editor
