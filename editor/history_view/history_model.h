#pragma once
// The document's History as a list model: row 0 is the state before any command ("<empty>"),
// row i the state after command i-1. It adapts the one History (never a second stack), like
// QUndoView shows a QUndoStack. The current row is History::index(); the clean row is marked.
#include <QAbstractListModel>

namespace glint::editor {

class Document;

class HistoryModel : public QAbstractListModel {
    Q_OBJECT
public:
    explicit HistoryModel(Document& document, QObject* parent = nullptr);
    ~HistoryModel() override;

    int rowCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    int currentRow() const;

private:
    void refresh();

    Document& document_;
    int listener_ = 0;
};

} // namespace glint::editor
