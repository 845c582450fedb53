#include "material_list_model.h"

#include "material_operations.h"
#include "swatch_renderer.h"

#include "editor/document/document.h"
#include "editor/preferences/retranslate.h"

#include <QPixmap>

#include <set>

namespace glint::editor {

MaterialListModel::MaterialListModel(Document& document, SwatchRenderer* swatches, QObject* parent)
    : QAbstractListModel(parent), document_(document), swatches_(swatches) {
    connect(&document_, &Document::changed, this, &MaterialListModel::onChanged);
    connect(&document_, &Document::sceneReplaced, this, [this] {
        beginResetModel();
        rebuild();
        endResetModel();
    });
    if (swatches_)
        connect(swatches_, &SwatchRenderer::swatchReady, this, [this](quint64 hash) {
            for (int row = 0; row < int(rows_.size()); ++row)
                if (hashes_[rows_[std::size_t(row)]] == hash) emit dataChanged(index(row), index(row), {Qt::DecorationRole});
        });
    rebuild();
}

void MaterialListModel::rebuild() {
    rows_.clear();
    hashes_.clear();
    for (const auto& [id, material] : document_.scene().materials) {
        rows_.push_back(id);
        hashRow(id);
    }
    countUsers();
    requestSwatches();
}

void MaterialListModel::countUsers() {
    users_.clear();
    for (const MaterialId id : rows_) users_[id] = int(materialUsers(document_.scene(), id).size());
}

void MaterialListModel::hashRow(MaterialId id) { hashes_[id] = SwatchRenderer::contentHash(document_.scene(), id); }

void MaterialListModel::requestSwatches() {
    if (!swatches_) return;
    std::set<std::uint64_t> wanted;
    for (const MaterialId id : rows_) wanted.insert(hashes_[id]);
    swatches_->keepOnly(wanted);
    for (const MaterialId id : rows_) swatches_->request(document_.scene(), id);
}

void MaterialListModel::onChanged(const ChangeSet& changes) {
    std::vector<MaterialId> now;
    for (const auto& [id, material] : document_.scene().materials) now.push_back(id);
    if (now != rows_) { // materials added or removed: few, and ids are stable
        beginResetModel();
        rebuild();
        endResetModel();
        return;
    }
    if (changes.has(Change::Material) || changes.has(Change::Assets)) {
        // A texture, image or sampler change names no material: hash them all again.
        const bool onlyNamed = changes.textures.empty() && changes.images.empty() && changes.samplers.empty() &&
                               !changes.has(Change::Assets);
        for (const MaterialId id : rows_)
            if (!onlyNamed || changes.materials.count(id)) hashRow(id);
        requestSwatches();
    }
    if (changes.has(Change::Geometry) || changes.has(Change::Structure) || changes.has(Change::Assets)) countUsers();
    if (!rows_.empty()) emit dataChanged(index(0), index(int(rows_.size()) - 1));
}

int MaterialListModel::rowCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : int(rows_.size()); }

MaterialId MaterialListModel::materialAt(const QModelIndex& index) const {
    if (!index.isValid() || index.row() < 0 || index.row() >= int(rows_.size())) return {};
    return rows_[std::size_t(index.row())];
}

QModelIndex MaterialListModel::indexOf(MaterialId id) const {
    for (int row = 0; row < int(rows_.size()); ++row)
        if (rows_[std::size_t(row)] == id) return index(row);
    return {};
}

int MaterialListModel::usersOf(MaterialId id) const {
    auto it = users_.find(id);
    return it == users_.end() ? 0 : it->second;
}

QVariant MaterialListModel::data(const QModelIndex& index, int role) const {
    const MaterialId id = materialAt(index);
    const Material* material = document_.scene().materials.find(id);
    if (!material) return {};
    const QString name = material->name.empty() ? tr("Material %1").arg(id.value) : QString::fromStdString(material->name);
    const int users = usersOf(id);
    switch (role) {
    case Qt::DisplayRole:
        return tr("%1\n%2").arg(name, countText("glint::editor::MaterialListModel", QT_TRANSLATE_N_NOOP("glint::editor::MaterialListModel", "%n users"),
                                                "%n user", users));
    case Qt::EditRole:
    case NameRole: return name;
    case Qt::ToolTipRole:
        return users == 0 ? tr("%1: no node uses it (Delete unused removes it)").arg(name)
                          : tr("%1: drag it onto a node in the outliner or the viewport to assign it").arg(name);
    case Qt::AccessibleTextRole: return name;
    case Qt::DecorationRole: {
        if (!swatches_) return {};
        auto it = hashes_.find(id);
        const QImage swatch = it == hashes_.end() ? QImage() : swatches_->cached(it->second);
        return swatch.isNull() ? QVariant() : QVariant(QPixmap::fromImage(swatch));
    }
    case IdRole: return id.value;
    case UsersRole: return users;
    case HashRole: {
        auto it = hashes_.find(id);
        return it == hashes_.end() ? QVariant() : QVariant(quint64(it->second));
    }
    default: return {};
    }
}

bool MaterialListModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    const MaterialId id = materialAt(index);
    if (!id || role != Qt::EditRole) return false;
    const QString error = renameMaterial(document_, id, value.toString());
    if (!error.isEmpty()) {
        emit editFailed(error);
        return false;
    }
    return true;
}

Qt::ItemFlags MaterialListModel::flags(const QModelIndex& index) const {
    if (!index.isValid()) return Qt::NoItemFlags;
    return Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsEditable | Qt::ItemIsDragEnabled | Qt::ItemNeverHasChildren;
}

QStringList MaterialListModel::mimeTypes() const { return {QString::fromLatin1(kMaterialMimeType)}; }

QMimeData* MaterialListModel::mimeData(const QModelIndexList& indexes) const {
    std::vector<MaterialId> ids;
    for (const QModelIndex& index : indexes)
        if (const MaterialId id = materialAt(index); id && std::find(ids.begin(), ids.end(), id) == ids.end()) ids.push_back(id);
    return encodeMaterials(ids);
}

} // namespace glint::editor
