#pragma once
// Every material of the document as a Qt list model, in id order (the file's order): the name
// (editable: a rename is an undoable command), the swatch, how many nodes use it. Built from the
// document and never owning it; rows follow the document's changed() signal. Rows drag out as
// kMaterialMimeType (material_operations.h) for drops on nodes.
#include "scene/core/ids.h"
#include "scene/history/change_set.h"

#include <QAbstractListModel>

#include <cstdint>
#include <map>
#include <vector>

namespace glint::editor {

class Document;
class SwatchRenderer;

class MaterialListModel : public QAbstractListModel {
    Q_OBJECT
public:
    enum Role { IdRole = Qt::UserRole + 1, UsersRole, NameRole, HashRole };

    // `swatches` may be null (no swatches: the decoration is empty).
    MaterialListModel(Document& document, SwatchRenderer* swatches, QObject* parent = nullptr);

    int rowCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    Qt::DropActions supportedDragActions() const override { return Qt::CopyAction | Qt::LinkAction; }
    QStringList mimeTypes() const override;
    QMimeData* mimeData(const QModelIndexList& indexes) const override;

    MaterialId materialAt(const QModelIndex& index) const;
    QModelIndex indexOf(MaterialId id) const;
    int usersOf(MaterialId id) const;

signals:
    void editFailed(const QString& message);

private:
    void rebuild();        // rows, users and hashes from scratch
    void onChanged(const ChangeSet& changes);
    void countUsers();
    void hashRow(MaterialId id);
    void requestSwatches();

    Document& document_;
    SwatchRenderer* swatches_;
    std::vector<MaterialId> rows_;
    std::map<MaterialId, int> users_;
    std::map<MaterialId, std::uint64_t> hashes_;
};

} // namespace glint::editor
