#include "outliner_model.h"

#include "editor/document/document.h"
#include "editor/document/edit_operations.h"
#include "editor/materials/material_operations.h"
#include "node_names.h"

#include <QApplication>
#include <QDataStream>
#include <QFont>
#include <QIODevice>
#include <QMimeData>
#include <QStyle>

namespace glint::editor {
namespace {

QString componentName(const Component& component) {
    if (std::holds_alternative<MeshInstance>(component)) return OutlinerModel::tr("Mesh");
    if (std::holds_alternative<Shape>(component)) return OutlinerModel::tr("Shape");
    if (std::holds_alternative<Light>(component)) return OutlinerModel::tr("Light");
    if (std::holds_alternative<Camera>(component)) return OutlinerModel::tr("Camera");
    return OutlinerModel::tr("Group");
}

QIcon componentIcon(const Component& component) {
    QStyle* style = QApplication::style();
    if (!style) return {};
    if (std::holds_alternative<Light>(component)) return style->standardIcon(QStyle::SP_DialogYesButton);
    if (std::holds_alternative<Camera>(component)) return style->standardIcon(QStyle::SP_ComputerIcon);
    if (std::holds_alternative<std::monostate>(component)) return style->standardIcon(QStyle::SP_DirIcon);
    return style->standardIcon(QStyle::SP_FileIcon);
}

} // namespace

OutlinerModel::OutlinerModel(Document& document, QObject* parent) : QAbstractItemModel(parent), document_(document) {
    connect(&document_, &Document::changed, this, &OutlinerModel::onChanged);
}

const std::vector<NodeId>& OutlinerModel::childrenOf(NodeId parent) const {
    if (!parent) return document_.scene().roots();
    return document_.scene().at(parent).children;
}

NodeId OutlinerModel::nodeAt(const QModelIndex& index) const {
    return index.isValid() ? NodeId{static_cast<std::uint32_t>(index.internalId())} : NodeId{};
}

QModelIndex OutlinerModel::index(int row, int column, const QModelIndex& parent) const {
    if (row < 0 || column < 0 || column >= ColumnCount) return {};
    if (parent.isValid() && parent.column() != NameColumn) return {};
    const NodeId parentId = nodeAt(parent);
    if (parentId && !document_.scene().contains(parentId)) return {};
    const auto& children = childrenOf(parentId);
    if (static_cast<std::size_t>(row) >= children.size()) return {};
    return createIndex(row, column, quintptr{children[static_cast<std::size_t>(row)].value});
}

QModelIndex OutlinerModel::parent(const QModelIndex& child) const {
    const Node* node = document_.scene().node(nodeAt(child));
    if (!node || !node->parent) return {};
    return indexOf(node->parent);
}

QModelIndex OutlinerModel::indexOf(NodeId id, int column) const {
    if (!document_.scene().contains(id)) return {};
    const int row = static_cast<int>(document_.scene().indexInParent(id));
    return createIndex(row, column, quintptr{id.value});
}

int OutlinerModel::rowCount(const QModelIndex& parent) const {
    if (parent.isValid() && parent.column() != NameColumn) return 0;
    const NodeId id = nodeAt(parent);
    if (id && !document_.scene().contains(id)) return 0;
    return static_cast<int>(childrenOf(id).size());
}

int OutlinerModel::columnCount(const QModelIndex&) const { return ColumnCount; }

QVariant OutlinerModel::data(const QModelIndex& index, int role) const {
    const Node* node = document_.scene().node(nodeAt(index));
    if (!node) return {};
    if (index.column() == NameColumn) {
        const Scene& scene = document_.scene();
        const NodeId id = nodeAt(index);
        const QString name = nodeDisplayName(scene, id); // derived (and shown in italics) when it has none
        switch (role) {
        case Qt::DisplayRole:
        case Qt::EditRole: return name;
        case Qt::DecorationRole: return componentIcon(node->component);
        case Qt::FontRole: {
            if (hasOwnName(scene, id)) return {};
            QFont font;
            font.setItalic(true);
            return font;
        }
        case Qt::ToolTipRole:
            return hasOwnName(scene, id) ? tr("%1 (%2)").arg(name, componentName(node->component))
                                         : tr("%1 (%2; the file gives it no name)").arg(name, componentName(node->component));
        case Qt::AccessibleTextRole: return tr("%1, %2").arg(name, componentName(node->component));
        default: return {};
        }
    }
    if (role == Qt::CheckStateRole) return node->visible ? Qt::Checked : Qt::Unchecked;
    if (role == Qt::ToolTipRole || role == Qt::AccessibleTextRole) return node->visible ? tr("Visible") : tr("Hidden");
    return {};
}

bool OutlinerModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    const NodeId id = nodeAt(index);
    QString error;
    if (index.column() == NameColumn && role == Qt::EditRole) {
        const QString name = value.toString().trimmed();
        if (name.isEmpty()) return false;
        // Confirming the shown derived name keeps the node unnamed (nothing is written).
        if (!hasOwnName(document_.scene(), id) && name == nodeDisplayName(document_.scene(), id)) return true;
        error = renameNode(document_, id, name);
    } else if (index.column() == VisibleColumn && role == Qt::CheckStateRole) {
        error = setVisible(document_, id, value.toInt() == Qt::Checked);
    } else {
        return false;
    }
    if (!error.isEmpty()) emit editFailed(error);
    return error.isEmpty();
}

QVariant OutlinerModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    return section == NameColumn ? tr("Name") : tr("Visible");
}

Qt::ItemFlags OutlinerModel::flags(const QModelIndex& index) const {
    if (!index.isValid()) return Qt::ItemIsDropEnabled;
    Qt::ItemFlags f = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    if (index.column() == NameColumn) f |= Qt::ItemIsEditable | Qt::ItemIsDragEnabled | Qt::ItemIsDropEnabled;
    else f |= Qt::ItemIsUserCheckable;
    return f;
}

QMimeData* OutlinerModel::mimeData(const QModelIndexList& indexes) const {
    QByteArray bytes;
    QDataStream out(&bytes, QIODevice::WriteOnly);
    QList<quint32> ids;
    for (const QModelIndex& index : indexes)
        if (index.column() == NameColumn && !ids.contains(nodeAt(index).value)) ids << nodeAt(index).value;
    out << ids;
    auto* data = new QMimeData;
    data->setData(kMimeType, bytes);
    return data;
}

std::vector<NodeId> OutlinerModel::decode(const QMimeData* data) {
    std::vector<NodeId> nodes;
    if (!data || !data->hasFormat(kMimeType)) return nodes;
    QByteArray bytes = data->data(kMimeType);
    QDataStream in(&bytes, QIODevice::ReadOnly);
    QList<quint32> ids;
    in >> ids;
    for (quint32 id : ids) nodes.push_back(NodeId{id});
    return nodes;
}

QStringList OutlinerModel::mimeTypes() const { return {kMimeType, QString::fromLatin1(kMaterialMimeType)}; }

bool OutlinerModel::canDropMimeData(const QMimeData* data, Qt::DropAction action, int row, int,
                                    const QModelIndex& parent) const {
    // A material lands on a node (not between nodes) that can show it.
    if (data && data->hasFormat(kMaterialMimeType))
        return row < 0 && !decodeMaterials(data).empty() && takesMaterial(document_.scene(), nodeAt(parent));
    if (action != Qt::MoveAction) return false;
    const std::vector<NodeId> nodes = decode(data);
    if (nodes.empty()) return false;
    const NodeId target = nodeAt(parent);
    for (NodeId id : nodes) {
        if (!document_.scene().contains(id)) return false;
        if (target && (id == target || document_.scene().isAncestor(id, target))) return false;
    }
    return true;
}

bool OutlinerModel::dropMimeData(const QMimeData* data, Qt::DropAction action, int row, int column,
                                 const QModelIndex& parent) {
    if (!canDropMimeData(data, action, row, column, parent)) return false;
    if (data->hasFormat(kMaterialMimeType)) {
        const MaterialId material = decodeMaterials(data).front();
        const NodeId node = nodeAt(parent);
        QMetaObject::invokeMethod(
            this,
            [this, material, node] {
                const QString error = assignMaterial(document_, material, {node});
                if (!error.isEmpty()) emit editFailed(error);
            },
            Qt::QueuedConnection);
        return true;
    }
    const std::vector<NodeId> nodes = decode(data);
    const NodeId target = nodeAt(parent);
    const std::size_t index = row < 0 ? SIZE_MAX : static_cast<std::size_t>(row);
    // The view is still inside its drop handler: change the model once it has returned.
    QMetaObject::invokeMethod(
        this,
        [this, nodes, target, index] {
            const QString error = reparentNodes(document_, nodes, target, index);
            if (!error.isEmpty()) emit editFailed(error);
        },
        Qt::QueuedConnection);
    return false; // the rows move through the document, not through removeRows
}

void OutlinerModel::onChanged(const ChangeSet& changes) {
    if (changes.has(Change::Structure)) {
        // Adds, removes and moves: rebuild the view of the tree (it is cheap; ids are stable).
        beginResetModel();
        endResetModel();
        return;
    }
    if (!changes.has(Change::Name) && !changes.has(Change::Visibility) && !changes.has(Change::Geometry) &&
        !changes.has(Change::Light) && !changes.has(Change::Camera))
        return;
    for (NodeId id : changes.nodes) {
        const QModelIndex first = indexOf(id, NameColumn);
        if (first.isValid()) emit dataChanged(first, indexOf(id, VisibleColumn));
    }
}

} // namespace glint::editor
