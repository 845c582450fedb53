#include "properties_panel.h"

#include "property_edits.h"
#include "sections.h"

#include "editor/document/document.h"

#include <QEvent>
#include <QLabel>
#include <QVBoxLayout>

namespace glint::editor {

PropertiesPanel::PropertiesPanel(Document& document, bool scene, QWidget* parent)
    : QScrollArea(parent), document_(document), scene_(scene) {
    setWidgetResizable(true);
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff); // the forms wrap to the dock's width
    setAccessibleName(scene ? tr("Scene settings") : tr("Properties"));
    connect(&document_, &Document::changed, this, &PropertiesPanel::update);
    connect(&document_, &Document::selectionChanged, this, &PropertiesPanel::update);
    connect(&document_, &Document::timeChanged, this, &PropertiesPanel::update); // keyed nodes' poses
    rebuild();
}

void PropertiesPanel::setViewportControls(ViewportControls controls) {
    viewportControls_ = std::move(controls);
    rebuild();
}

void PropertiesPanel::changeEvent(QEvent* event) {
    QScrollArea::changeEvent(event);
    // The forms hold their labels as plain text: build them again in the new language.
    if (event->type() == QEvent::LanguageChange && built_) rebuild();
}

PropertiesPanel::Key PropertiesPanel::currentKey() const {
    Key key;
    if (scene_) return key;
    key.node = document_.currentNode();
    const Node* node = document_.scene().node(key.node);
    if (!node) return {};
    key.component = node->component.index();
    key.primitive = key.node == primitiveNode_ ? primitive_ : 0;
    key.material = nodeMaterial(document_.scene(), key.node, key.primitive);
    key.texturedSlots = texturedSlots(document_.scene(), key.material);
    if (const glint::Light* light = node->get<glint::Light>()) {
        key.lightType = static_cast<int>(light->type);
        if (light->type == glint::LightType::Area) key.areaShape = static_cast<int>(light->areaShape);
    }
    if (const glint::Shape* shape = node->get<glint::Shape>()) key.shapeKind = static_cast<int>(shape->kind);
    if (const glint::Camera* camera = node->get<glint::Camera>()) key.projection = static_cast<int>(camera->projection);
    return key;
}

void PropertiesPanel::update() {
    if (!built_ || currentKey() != shown_) {
        rebuild();
        return;
    }
    for (PropertyForm* form : forms_) form->refresh();
}

void PropertiesPanel::rebuild() {
    // The old forms may be mid-signal (a combo box that caused this change): delete them later.
    // (QScrollArea::setWidget would delete the old one at once.)
    if (QWidget* old = takeWidget()) old->deleteLater();
    forms_.clear();
    content_ = new QWidget;
    layout_ = new QVBoxLayout(content_);
    shown_ = currentKey();
    built_ = true;
    const Report report = [this](const QString& text) { emit message(text); };
    auto add = [this](PropertyForm* form) {
        forms_.push_back(form);
        layout_->addWidget(form);
    };
    if (scene_) {
        if (viewportControls_) add(makeViewportForm(document_, viewportControls_, content_));
        add(makeRenderForm(document_, report, content_));
        add(makeReconstructionForm(document_, report, content_));
        add(makeProjectForm(document_, report, content_));
        add(makeEnvironmentForm(document_, report, content_));
        add(makeFogForm(document_, report, content_));
    } else if (!shown_.node) {
        auto* hint = new QLabel(tr("Select a node in the outliner or the viewport to edit it."), content_);
        hint->setWordWrap(true);
        layout_->addWidget(hint);
    } else {
        const Node& node = document_.scene().at(shown_.node);
        add(makeNodeForm(document_, shown_.node, report, content_));
        add(makeTransformForm(document_, shown_.node, report, content_));
        if (node.get<glint::Shape>()) add(makeShapeForm(document_, shown_.node, report, content_));
        if (node.get<glint::Light>()) add(makeLightForm(document_, shown_.node, report, content_));
        if (node.get<glint::Camera>()) add(makeCameraForm(document_, shown_.node, report, content_));
        if (node.get<glint::Shape>() || node.get<glint::MeshInstance>()) {
            const NodeId id = shown_.node;
            add(makeMaterialSlotsForm(
                document_, id, shown_.primitive,
                [this, id](std::size_t primitive) {
                    primitiveNode_ = id;
                    primitive_ = primitive;
                    // Not inside the clicked button's signal: it is deleted with its form.
                    QMetaObject::invokeMethod(this, &PropertiesPanel::update, Qt::QueuedConnection);
                },
                report, content_));
        }
        if (shown_.material) add(makeMaterialForm(document_, shown_.material, report, content_));
    }
    layout_->addStretch();
    setWidget(content_);
}

} // namespace glint::editor
