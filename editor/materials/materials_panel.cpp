#include "materials_panel.h"

#include "material_list_model.h"
#include "material_operations.h"
#include "material_presets.h"
#include "swatch_renderer.h"

#include "editor/document/document.h"
#include "editor/preferences/retranslate.h"

#include <QAction>
#include <QHBoxLayout>
#include <QItemSelectionModel>
#include <QLineEdit>
#include <QListView>
#include <QMenu>
#include <QSortFilterProxyModel>
#include <QToolButton>
#include <QVBoxLayout>

namespace glint::editor {
namespace {

QToolButton* button(QWidget* parent, const char* objectName, const char* text, const char* tip) {
    auto* b = new QToolButton(parent);
    b->setObjectName(objectName);
    keepTranslated(b, TextRole::Text, "glint::editor::MaterialsPanel", text);
    keepTranslated(b, TextRole::ToolTip, "glint::editor::MaterialsPanel", tip);
    keepTranslated(b, TextRole::AccessibleName, "glint::editor::MaterialsPanel", text);
    return b;
}

} // namespace

MaterialsPanel::MaterialsPanel(Document& document, QWidget* parent, bool renderSwatches)
    : QWidget(parent), document_(document) {
    if (renderSwatches) swatches_ = new SwatchRenderer(this);
    model_ = new MaterialListModel(document_, swatches_, this);
    proxy_ = new QSortFilterProxyModel(this);
    proxy_->setSourceModel(model_);
    proxy_->setFilterRole(MaterialListModel::NameRole);
    proxy_->setFilterCaseSensitivity(Qt::CaseInsensitive);
    connect(model_, &MaterialListModel::editFailed, this, &MaterialsPanel::message);

    search_ = new QLineEdit(this);
    keepTranslated(search_, TextRole::Placeholder, staticMetaObject.className(), QT_TR_NOOP("Search materials"));
    keepTranslated(search_, TextRole::AccessibleName, staticMetaObject.className(), QT_TR_NOOP("Material search"));
    search_->setClearButtonEnabled(true);
    connect(search_, &QLineEdit::textChanged, proxy_, &QSortFilterProxyModel::setFilterFixedString);

    view_ = new QListView(this);
    view_->setModel(proxy_);
    keepTranslated(view_, TextRole::AccessibleName, staticMetaObject.className(), QT_TR_NOOP("Materials"));
    view_->setIconSize(QSize(SwatchRenderer::kSize, SwatchRenderer::kSize));
    view_->setUniformItemSizes(true);
    view_->setSelectionMode(QAbstractItemView::SingleSelection);
    view_->setDragEnabled(true);
    view_->setDragDropMode(QAbstractItemView::DragOnly);
    view_->setDefaultDropAction(Qt::CopyAction);
    view_->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
    connect(view_->selectionModel(), &QItemSelectionModel::currentChanged, this, &MaterialsPanel::updateButtons);
    connect(model_, &QAbstractItemModel::modelReset, this, &MaterialsPanel::updateButtons);

    auto* newButton = button(this, "materials.new", QT_TR_NOOP("New"), QT_TR_NOOP("A new material from a preset"));
    newButton->setPopupMode(QToolButton::InstantPopup);
    newMenu_ = new QMenu(newButton);
    for (const MaterialPreset& preset : materialPresets()) {
        QAction* action = newMenu_->addAction(QString());
        action->setObjectName(QStringLiteral("materials.new.%1").arg(QLatin1String(preset.id)));
        keepTranslated(action, TextRole::Text, "glint::editor::MaterialPresets", preset.title);
        connect(action, &QAction::triggered, this, [this, id = QString::fromLatin1(preset.id)] { createFromPreset(id); });
    }
    newButton->setMenu(newMenu_);
    duplicate_ = button(this, "materials.duplicate", QT_TR_NOOP("Duplicate"), QT_TR_NOOP("A copy of the selected material"));
    rename_ = button(this, "materials.rename", QT_TR_NOOP("Rename"), QT_TR_NOOP("Rename the selected material"));
    deleteUnused_ = button(this, "materials.deleteUnused", QT_TR_NOOP("Delete unused"),
                           QT_TR_NOOP("Remove every material no node uses"));
    assign_ = button(this, "materials.assign", QT_TR_NOOP("Assign to selection"),
                     QT_TR_NOOP("Give the selected material to every selected shape and mesh (one undo step)"));
    connect(duplicate_, &QToolButton::clicked, this, &MaterialsPanel::duplicateCurrent);
    connect(rename_, &QToolButton::clicked, this, &MaterialsPanel::renameCurrent);
    connect(deleteUnused_, &QToolButton::clicked, this, &MaterialsPanel::deleteUnused);
    connect(assign_, &QToolButton::clicked, this, &MaterialsPanel::assignToSelection);
    connect(&document_, &Document::selectionChanged, this, &MaterialsPanel::updateButtons);

    auto* buttons = new QHBoxLayout;
    buttons->setSpacing(2);
    for (QToolButton* b : {newButton, duplicate_, rename_, deleteUnused_}) buttons->addWidget(b);
    buttons->addStretch();
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addWidget(search_);
    layout->addLayout(buttons);
    layout->addWidget(view_, 1);
    layout->addWidget(assign_);
    updateButtons();
}

MaterialsPanel::~MaterialsPanel() = default;

MaterialId MaterialsPanel::currentMaterial() const {
    return model_->materialAt(proxy_->mapToSource(view_->selectionModel()->currentIndex()));
}

void MaterialsPanel::selectMaterial(MaterialId id) {
    const QModelIndex index = proxy_->mapFromSource(model_->indexOf(id));
    view_->selectionModel()->setCurrentIndex(index, QItemSelectionModel::ClearAndSelect);
    if (index.isValid()) view_->scrollTo(index);
}

void MaterialsPanel::updateButtons() {
    const bool any = currentMaterial().valid();
    duplicate_->setEnabled(any);
    rename_->setEnabled(any);
    assign_->setEnabled(any && !document_.selection().empty());
}

void MaterialsPanel::createFromPreset(const QString& presetId) {
    const MaterialPreset* preset = findMaterialPreset(presetId);
    if (!preset) return;
    Material value = preset->value;
    value.name = presetTitle(*preset).toStdString(); // named in the language of the moment
    MaterialId added;
    const QString error = newMaterial(document_, std::move(value), &added);
    if (!error.isEmpty()) emit message(error);
    else selectMaterial(added);
}

void MaterialsPanel::duplicateCurrent() {
    MaterialId added;
    const QString error = duplicateMaterial(document_, currentMaterial(), &added);
    if (!error.isEmpty()) emit message(error);
    else selectMaterial(added);
}

void MaterialsPanel::renameCurrent() {
    const QModelIndex index = view_->selectionModel()->currentIndex();
    if (index.isValid()) view_->edit(index);
}

void MaterialsPanel::deleteUnused() {
    int removed = 0;
    const QString error = deleteUnusedMaterials(document_, &removed);
    if (!error.isEmpty()) emit message(error);
    else emit message(countText(staticMetaObject.className(), QT_TR_N_NOOP("%n unused materials removed."),
                                "%n unused material removed.", removed));
}

void MaterialsPanel::assignToSelection() {
    const MaterialId material = currentMaterial();
    if (!material) {
        emit message(tr("Select a material in the list first."));
        return;
    }
    const QString error = assignMaterial(document_, material, document_.selection());
    if (!error.isEmpty()) emit message(error);
}

} // namespace glint::editor
