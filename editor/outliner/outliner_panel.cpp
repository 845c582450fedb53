#include "outliner_panel.h"

#include "outliner_model.h"

#include "editor/document/document.h"
#include "editor/document/edit_operations.h"
#include "editor/document/labelled_command.h"
#include "editor/document/portal_edits.h"
#include "editor/document/scene_templates.h"
#include "editor/preferences/retranslate.h"
#include "scene/history/settings_commands.h"

#include <QEvent>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLineEdit>
#include <QMenu>
#include <QSortFilterProxyModel>
#include <QToolButton>
#include <QTreeView>
#include <QVBoxLayout>

#include <exception>
#include <memory>

namespace glint::editor {

OutlinerPanel::OutlinerPanel(Document& document, QWidget* parent) : QWidget(parent), document_(document) {
    model_ = new OutlinerModel(document_, this);
    proxy_ = new QSortFilterProxyModel(this);
    proxy_->setSourceModel(model_);
    proxy_->setRecursiveFilteringEnabled(true); // keep the parents of a match, so it stays in place
    proxy_->setFilterCaseSensitivity(Qt::CaseInsensitive);
    proxy_->setFilterKeyColumn(OutlinerModel::NameColumn);

    filter_ = new QLineEdit(this);
    keepTranslated(filter_, TextRole::Placeholder, staticMetaObject.className(), QT_TR_NOOP("Filter by name"));
    keepTranslated(filter_, TextRole::AccessibleName, staticMetaObject.className(), QT_TR_NOOP("Outliner filter"));
    filter_->setClearButtonEnabled(true);
    connect(filter_, &QLineEdit::textChanged, this, [this](const QString& text) {
        proxy_->setFilterFixedString(text);
        view_->expandAll();
        syncFromDocument();
    });

    auto* addButton = new QToolButton(this);
    keepTranslated(addButton, TextRole::Text, staticMetaObject.className(), QT_TR_NOOP("Add"));
    keepTranslated(addButton, TextRole::AccessibleName, staticMetaObject.className(), QT_TR_NOOP("Add a shape, light or camera"));
    addButton->setPopupMode(QToolButton::InstantPopup);
    buildAddMenu();
    addButton->setMenu(addMenu_);

    view_ = new QTreeView(this);
    view_->setModel(proxy_);
    keepTranslated(view_, TextRole::AccessibleName, staticMetaObject.className(), QT_TR_NOOP("Scene outliner"));
    view_->setSelectionMode(QAbstractItemView::ExtendedSelection);
    view_->setSelectionBehavior(QAbstractItemView::SelectRows);
    view_->setDragDropMode(QAbstractItemView::DragDrop);
    view_->setDefaultDropAction(Qt::MoveAction);
    view_->setDragEnabled(true);
    view_->setAcceptDrops(true);
    view_->setDropIndicatorShown(true);
    view_->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
    view_->setContextMenuPolicy(Qt::CustomContextMenu);
    view_->header()->setStretchLastSection(false);
    view_->header()->setSectionResizeMode(OutlinerModel::NameColumn, QHeaderView::Stretch);
    view_->header()->setSectionResizeMode(OutlinerModel::VisibleColumn, QHeaderView::ResizeToContents);
    connect(view_, &QWidget::customContextMenuRequested, this, &OutlinerPanel::showContextMenu);
    connect(view_->selectionModel(), &QItemSelectionModel::selectionChanged, this, &OutlinerPanel::syncToDocument);
    connect(model_, &OutlinerModel::modelReset, this, [this] {
        view_->expandAll();
        syncFromDocument();
    });
    connect(model_, &OutlinerModel::editFailed, this, &OutlinerPanel::message);
    connect(&document_, &Document::selectionChanged, this, &OutlinerPanel::syncFromDocument);

    auto* top = new QHBoxLayout;
    top->addWidget(filter_);
    top->addWidget(addButton);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addLayout(top);
    layout->addWidget(view_);
    view_->expandAll();
}

void OutlinerPanel::buildAddMenu() {
    // Titles follow the language (retranslate.h); a new node is named in the language of the moment.
    addMenu_ = new QMenu(this);
    keepTranslated(addMenu_, TextRole::Title, staticMetaObject.className(), QT_TR_NOOP("Add"));
    auto add = [this](QMenu* menu, const char* name, Component component) {
        QAction* action = menu->addAction(QString());
        keepTranslated(action, TextRole::Text, staticMetaObject.className(), name);
        connect(action, &QAction::triggered, this, [this, action, component] {
            const QString error = addNode(document_, action->text(), component);
            if (!error.isEmpty()) emit message(error);
        });
    };
    QMenu* shapes = addMenu_->addMenu(QString());
    keepTranslated(shapes, TextRole::Title, staticMetaObject.className(), QT_TR_NOOP("Shape"));
    add(shapes, QT_TR_NOOP("Sphere"), defaultShape(ShapeKind::Sphere));
    add(shapes, QT_TR_NOOP("Box"), defaultShape(ShapeKind::Box));
    add(shapes, QT_TR_NOOP("Quad"), defaultShape(ShapeKind::Quad));
    add(shapes, QT_TR_NOOP("Disk"), defaultShape(ShapeKind::Disk));
    add(shapes, QT_TR_NOOP("Cylinder"), defaultShape(ShapeKind::Cylinder));
    add(shapes, QT_TR_NOOP("Ground plane"), defaultShape(ShapeKind::GroundPlane));
    QAction* portals = shapes->addAction(QString());
    keepTranslated(portals, TextRole::Text, staticMetaObject.className(), QT_TR_NOOP("Portal pair"));
    connect(portals, &QAction::triggered, this, [this] {
        const QString error = addPortalPair(document_);
        if (!error.isEmpty()) emit message(error);
    });
    QMenu* lights = addMenu_->addMenu(QString());
    keepTranslated(lights, TextRole::Title, staticMetaObject.className(), QT_TR_NOOP("Light"));
    add(lights, QT_TR_NOOP("Point light"), defaultLight(LightType::Point));
    add(lights, QT_TR_NOOP("Spot light"), defaultLight(LightType::Spot));
    add(lights, QT_TR_NOOP("Sun"), defaultLight(LightType::Sun));
    add(lights, QT_TR_NOOP("Area rectangle"), defaultAreaLight(AreaShape::Rectangle));
    add(lights, QT_TR_NOOP("Area disk"), defaultAreaLight(AreaShape::Disk));
    add(lights, QT_TR_NOOP("Area sphere"), defaultAreaLight(AreaShape::Sphere));
    // Most glTF models carry no light: the Studio template's lighting, in one undoable step.
    lights->addSeparator();
    QAction* studio = lights->addAction(QString());
    studio->setObjectName(QStringLiteral("add.light.studio_environment"));
    keepTranslated(studio, TextRole::Text, staticMetaObject.className(), QT_TR_NOOP("Studio environment"));
    connect(studio, &QAction::triggered, this, [this] {
        try {
            document_.push(withLabel(std::make_unique<SetProjectSettings>(withStudioLighting(document_.scene().settings)),
                                     QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Add studio environment")));
        } catch (const std::exception& e) {
            emit message(QString::fromStdString(e.what()));
        }
    });
    add(addMenu_, QT_TR_NOOP("Camera"), defaultCamera());
    add(addMenu_, QT_TR_NOOP("Empty group"), Component{});
}

void OutlinerPanel::syncFromDocument() {
    if (syncing_) return;
    syncing_ = true;
    QItemSelection selection;
    QModelIndex current;
    for (NodeId id : document_.selection()) {
        const QModelIndex index = proxy_->mapFromSource(model_->indexOf(id));
        if (!index.isValid()) continue;
        selection.select(index, index.siblingAtColumn(OutlinerModel::VisibleColumn));
        current = index;
    }
    view_->selectionModel()->select(selection, QItemSelectionModel::ClearAndSelect);
    if (current.isValid()) {
        view_->selectionModel()->setCurrentIndex(current, QItemSelectionModel::NoUpdate);
        view_->scrollTo(current);
    }
    syncing_ = false;
}

void OutlinerPanel::syncToDocument() {
    if (syncing_) return;
    syncing_ = true;
    std::vector<NodeId> nodes;
    for (const QModelIndex& index : view_->selectionModel()->selectedRows(OutlinerModel::NameColumn))
        nodes.push_back(model_->nodeAt(proxy_->mapToSource(index)));
    // The current item is the one the user clicked last: it becomes the document's current node.
    const NodeId current = model_->nodeAt(proxy_->mapToSource(view_->selectionModel()->currentIndex()));
    auto it = std::find(nodes.begin(), nodes.end(), current);
    if (it != nodes.end()) std::rotate(it, it + 1, nodes.end());
    document_.setSelection(std::move(nodes));
    syncing_ = false;
}

void OutlinerPanel::showContextMenu(const QPoint& pos) {
    QMenu menu(this);
    const QModelIndex index = view_->indexAt(pos);
    if (index.isValid()) {
        menu.addAction(tr("Rename"), this, [this, index] { view_->edit(index.siblingAtColumn(0)); });
        menu.addAction(tr("Duplicate"), this, [this] {
            const QString error = duplicateSelection(document_);
            if (!error.isEmpty()) emit message(error);
        });
        menu.addAction(tr("Delete"), this, [this] {
            const QString error = deleteSelection(document_);
            if (!error.isEmpty()) emit message(error);
        });
        menu.addSeparator();
    }
    menu.addMenu(addMenu_);
    menu.exec(view_->viewport()->mapToGlobal(pos));
}

void OutlinerPanel::changeEvent(QEvent* event) {
    QWidget::changeEvent(event);
    // The kept texts are set by the window (retranslate.h); the model's headers are read on demand.
    if (event->type() == QEvent::LanguageChange)
        emit model_->headerDataChanged(Qt::Horizontal, 0, model_->columnCount() - 1);
}

} // namespace glint::editor
