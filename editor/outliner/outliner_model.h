#pragma once
// The scene graph as a Qt item model, built from the document and never owning it (Blender's
// outliner builds its tree from the data the same way). Column 0 is the name (editable) with an
// icon for the component, column 1 the visibility check box. Edits and drops push commands;
// the model follows the document's changed() signal like every other view.
#include "scene/core/ids.h"
#include "scene/history/change_set.h"

#include <QAbstractItemModel>

namespace glint::editor {

class Document;

class OutlinerModel : public QAbstractItemModel {
    Q_OBJECT
public:
    enum Column { NameColumn = 0, VisibleColumn = 1, ColumnCount = 2 };
    static constexpr const char* kMimeType = "application/x-glint-node-ids";

    explicit OutlinerModel(Document& document, QObject* parent = nullptr);

    QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
    QModelIndex parent(const QModelIndex& child) const override;
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;

    // Nodes move (reparent); materials from the Materials panel copy onto the node they land on.
    Qt::DropActions supportedDropActions() const override { return Qt::MoveAction | Qt::CopyAction; }
    QStringList mimeTypes() const override;
    QMimeData* mimeData(const QModelIndexList& indexes) const override;
    bool canDropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                         const QModelIndex& parent) const override;
    bool dropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column, const QModelIndex& parent) override;

    NodeId nodeAt(const QModelIndex& index) const;
    QModelIndex indexOf(NodeId id, int column = NameColumn) const;

signals:
    void editFailed(const QString& message);

private:
    void onChanged(const ChangeSet& changes);
    const std::vector<NodeId>& childrenOf(NodeId parent) const;
    static std::vector<NodeId> decode(const QMimeData* data);

    Document& document_;
};

} // namespace glint::editor
