// The outliner, properties and history panels on a document, without GL (offscreen platform):
// selection both ways, properties following the selection, material edits through undo/redo,
// and a slider drag as one undo step.
#include "editor_fixtures.h"

#include "editor/document/edit_operations.h"
#include "editor/history_view/command_labels.h"
#include "editor/history_view/history_model.h"
#include "editor/preferences/language.h"
#include "scene/history/set_node_field.h"
#include "editor/history_view/history_panel.h"
#include "editor/outliner/outliner_model.h"
#include "editor/outliner/outliner_panel.h"
#include "editor/properties/properties_panel.h"
#include "editor/properties/property_form.h"

#include <QApplication>
#include <QColorDialog>
#include <QComboBox>
#include <QScrollBar>
#include <QWheelEvent>
#include <QLabel>
#include <QPushButton>
#include <QTimer>

#include <cmath>
#include <functional>

#include <glm/gtc/quaternion.hpp>
#include <QDoubleSpinBox>
#include <QItemSelectionModel>
#include <QLineEdit>
#include <QListView>
#include <QSlider>
#include <QSortFilterProxyModel>
#include <QTreeView>

using namespace glint;
using namespace glint::editor;
using namespace glint::editor::test;

namespace {

const Material& materialNamed(const Document& document, const std::string& name) {
    for (const auto& [id, material] : document.scene().materials)
        if (material.name == name) return material;
    throw std::runtime_error("no material " + name);
}

} // namespace

class PanelsTest : public QObject {
    Q_OBJECT
private slots:
    void outlinerSelectionFollowsBothWays();
    void propertiesFollowTheSelection();
    void materialColourUndoRedoIsExact();
    void sliderDragIsOneUndoStep();
    void aFieldChangedWithSeveralSelectedChangesAll();
    void historyPanelClickJumps();
    void filterKeepsMatchesAndTheirParents();
    void pickedColourIsStoredLinearAndShownAsPicked();
    void fieldsFitTheKindAndTheDock();
    void undoLabelsSayWhatHappened();
    void wheelScrollsThePanelNotTheFields();
};

void PanelsTest::outlinerSelectionFollowsBothWays() {
    Document document;
    QCOMPARE(document.open(cornellBox()), QString());
    OutlinerPanel panel(document);
    QTreeView& view = panel.view();
    const QModelIndex row = view.model()->index(3, 0);
    view.selectionModel()->setCurrentIndex(row, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
    QCOMPARE(document.currentNode(), nodeNamed(document, "right_wall_green"));
    document.setSelection({nodeNamed(document, "floor"), nodeNamed(document, "light")});
    const QModelIndexList rows = view.selectionModel()->selectedRows();
    QCOMPARE(rows.size(), 2);
    QCOMPARE(rows[0].data().toString() + rows[1].data().toString(), QString("floorlight"));
}

void PanelsTest::propertiesFollowTheSelection() {
    Document document;
    QCOMPARE(document.open(cornellBox()), QString());
    PropertiesPanel panel(document, false);
    QVERIFY(panel.forms().empty());
    document.setSelection({nodeNamed(document, "left_wall_red")});
    QCoreApplication::processEvents();
    QVERIFY(panel.forms().size() >= 3); // node, transform, material
    auto* name = fieldNamed<QLineEdit>(panel, "Name");
    QVERIFY(name);
    QCOMPARE(name->text(), QString("left_wall_red"));
    document.setSelection({nodeNamed(document, "camera")});
    QCoreApplication::processEvents();
    QCOMPARE(fieldNamed<QLineEdit>(panel, "Name")->text(), QString("camera"));
    QVERIFY(fieldNamed<FloatField>(panel, "Vertical field of view (degrees)"));
}

void PanelsTest::materialColourUndoRedoIsExact() {
    Document document;
    QCOMPARE(document.open(cornellBox()), QString());
    PropertiesPanel panel(document, false);
    document.setSelection({nodeNamed(document, "left_wall_red")});
    QCoreApplication::processEvents();
    auto* colour = fieldNamed<ColorField>(panel, "Base colour");
    QVERIFY(colour);
    const glm::vec4 original = materialNamed(document, "red").baseColorFactor;
    const QColor chosen = QColor::fromRgbF(0.25f, 0.5f, 0.75f);
    emit colour->edited(chosen);
    const glm::vec4 edited = materialNamed(document, "red").baseColorFactor;
    QCOMPARE(edited, glm::vec4(toLinear(chosen), original.w));
    document.undo();
    QCOMPARE(materialNamed(document, "red").baseColorFactor, original); // exact, not within a tolerance
    QCOMPARE(colour->color(), toQColor(original.x, original.y, original.z));
    document.redo();
    QCOMPARE(materialNamed(document, "red").baseColorFactor, edited);
    QCOMPARE(colour->color().name(), chosen.name());
}

// Issue 17, item 6: picking #CC2222 showed #F16666 and stored the sRGB numbers as linear ones.
// glTF's factors are linear: the picker shows and takes sRGB, the file gets the linear value.
void PanelsTest::pickedColourIsStoredLinearAndShownAsPicked() {
    Document document;
    QCOMPARE(document.open(cornellBox()), QString());
    PropertiesPanel panel(document, false);
    panel.show();
    document.setSelection({nodeNamed(document, "left_wall_red")});
    QCoreApplication::processEvents();
    const auto pick = [&](const QString& field, const QColor& colour) {
        auto* swatch = fieldNamed<ColorField>(panel, field);
        QVERIFY(swatch);
        bool answered = false;
        QTimer::singleShot(0, [&] { // the dialog runs modally inside the click
            auto* dialog = qobject_cast<QColorDialog*>(QApplication::activeModalWidget());
            QVERIFY(dialog);
            // The dialog opens on the colour the swatch shows.
            QCOMPARE(dialog->currentColor().name(), swatch->color().name());
            dialog->setCurrentColor(colour);
            dialog->accept();
            answered = true;
        });
        QTest::mouseClick(swatch->findChild<QPushButton*>(), Qt::LeftButton);
        QVERIFY(answered);
    };
    pick("Base colour", QColor("#CC2222"));
    const glm::vec4 base = materialNamed(document, "red").baseColorFactor;
    QVERIFY2(std::abs(base.x - 0.6038f) < 1e-3f && std::abs(base.y - 0.0160f) < 1e-3f && std::abs(base.z - 0.0160f) < 1e-3f,
             qPrintable(QString("%1 %2 %3").arg(base.x).arg(base.y).arg(base.z)));
    auto* swatch = fieldNamed<ColorField>(panel, "Base colour");
    QCOMPARE(swatch->color().name(), QString("#cc2222"));
    QVERIFY2(swatch->findChild<QPushButton*>()->styleSheet().contains("#cc2222"), qPrintable(swatch->findChild<QPushButton*>()->styleSheet()));
    // The same for the emission colour.
    pick("Emission", QColor("#808080"));
    const glm::vec3 emission = materialNamed(document, "red").emissiveFactor;
    QVERIFY2(std::abs(emission.x - 0.2158f) < 1e-3f, qPrintable(QString::number(emission.x)));
    QCOMPARE(fieldNamed<ColorField>(panel, "Emission")->color().name(), QString("#808080"));
}

// Issue 17: a sphere showed Height and Size, a sun Range and cone angles; the ground plane's sizes
// did nothing; at the dock's default width sliders were stubs and spin boxes lost their arrows.
void PanelsTest::fieldsFitTheKindAndTheDock() {
    Document document;
    PropertiesPanel panel(document, false);
    panel.resize(380, 900); // the dock's default width
    panel.show();
    QCOMPARE(addNode(document, "ball", defaultShape(ShapeKind::Sphere)), QString());
    QCoreApplication::processEvents();
    const auto shown = [&](const char* name) { return fieldNamed<QDoubleSpinBox>(panel, name) != nullptr; };
    QVERIFY(shown("Radius (m)"));
    QVERIFY(!shown("Height (m)") && !shown("Size X (m)"));
    // Every slider has room to move and every spin box is whole, arrows included.
    QTest::qWait(0);
    for (FloatField* field : panel.findChildren<FloatField*>()) {
        QVERIFY2(field->slider()->width() >= 60, qPrintable(QString("%1: slider %2 px").arg(field->slider()->accessibleName()).arg(field->slider()->width())));
        const QPoint right = field->spinBox()->mapTo(panel.viewport(), QPoint(field->spinBox()->width(), 0));
        QVERIFY2(right.x() <= panel.viewport()->width(), qPrintable(field->spinBox()->accessibleName()));
        QVERIFY(field->spinBox()->width() >= field->spinBox()->minimumSizeHint().width() || field->spinBox()->width() >= 60);
    }
    auto* kind = fieldNamed<QComboBox>(panel, "Kind");
    QVERIFY(kind);
    const auto chooseKind = [&](ShapeKind k) {
        kind->setCurrentIndex(int(k));
        emit kind->activated(int(k));
        QCoreApplication::processEvents();
        QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
        kind = fieldNamed<QComboBox>(panel, "Kind");
    };
    chooseKind(ShapeKind::Cylinder);
    QVERIFY(shown("Radius (m)") && shown("Height (m)") && !shown("Size X (m)"));
    chooseKind(ShapeKind::Box);
    QVERIFY(!shown("Radius (m)") && shown("Size X (m)") && shown("Size Y (m)") && shown("Size Z (m)"));
    chooseKind(ShapeKind::Quad);
    QVERIFY(shown("Size X (m)") && !shown("Size Y (m)") && shown("Size Z (m)"));
    chooseKind(ShapeKind::GroundPlane);
    QVERIFY(!shown("Radius (m)") && !shown("Size X (m)") && !shown("Height (m)"));
    bool said = false;
    for (QLabel* label : panel.findChildren<QLabel*>()) said = said || label->text().contains("infinite plane");
    QVERIFY(said);
    QCOMPARE(addNode(document, "sun", defaultLight(LightType::Sun)), QString());
    QCoreApplication::processEvents();
    QVERIFY(shown("Sun angular diameter (degrees)") && !shown("Range (m, 0 = infinite)") && !shown("Inner cone (degrees)"));
    QCOMPARE(addNode(document, "spot", defaultLight(LightType::Spot)), QString());
    QCoreApplication::processEvents();
    QVERIFY(shown("Range (m, 0 = infinite)") && shown("Inner cone (degrees)") && shown("Outer cone (degrees)"));
    QVERIFY(!shown("Sun angular diameter (degrees)"));
}

// Every gizmo drag was "Move" and every Scene tab edit "Edit settings" in the undo history (issue 17).
void PanelsTest::undoLabelsSayWhatHappened() {
    Document document;
    QCOMPARE(document.open(cornellBox()), QString());
    HistoryModel history(document);
    const auto lastLabel = [&] {
        QCoreApplication::processEvents(); // the model follows the history queued
        return history.index(history.rowCount() - 1).data().toString();
    };
    const NodeId block = nodeNamed(document, "tall_block");
    // What the gizmo pushes: one SetTransform per mouse move, one interaction per drag.
    const auto drag = [&](const std::function<void(Transform&, float)>& change) {
        const std::uint64_t serial = document.beginInteraction();
        const Transform start = document.scene().at(block).local;
        for (float t : {0.25f, 0.5f, 1.0f}) {
            Transform local = start;
            change(local, t);
            auto command = std::make_unique<SetTransform>(block, local);
            command->interaction = serial;
            document.push(std::move(command));
        }
    };
    const std::size_t before = document.history().count();
    drag([](Transform& local, float t) { local.rotation = glm::angleAxis(t, glm::vec3(0, 1, 0)) * local.rotation; });
    QCOMPARE(document.history().count(), before + 1); // still one step
    QCOMPARE(lastLabel(), QString("Rotate"));
    drag([](Transform& local, float t) { local.scale *= 1.0f + t; });
    QCOMPARE(lastLabel(), QString("Scale"));
    drag([](Transform& local, float t) { local.translation.x += t; });
    QCOMPARE(lastLabel(), QString("Move"));
    QCOMPARE(document.history().count(), before + 3);
    document.undo();
    QCOMPARE(lastLabel(), QString("Move")); // undone, still listed

    // The Scene tab: an exposure drag, a tonemapper choice.
    PropertiesPanel scene(document, true);
    auto* exposure = fieldNamed<FloatField>(scene, "Exposure (EV)");
    QVERIFY(exposure);
    exposure->slider()->setSliderDown(true);
    for (int position : {550, 600, 650}) exposure->slider()->setValue(position);
    exposure->slider()->setSliderDown(false);
    QCOMPARE(lastLabel(), QString("Change exposure"));
    auto* tonemapper = fieldNamed<QComboBox>(scene, "Tonemapper");
    QVERIFY(tonemapper);
    tonemapper->setCurrentIndex(2);
    emit tonemapper->activated(2);
    QCOMPARE(lastLabel(), QString("Change tonemapper"));
    auto* goal = fieldNamed<QComboBox>(scene, "Adaptive goal");
    QVERIFY(goal);
    goal->setCurrentIndex(1);
    emit goal->activated(1);
    QCOMPARE(lastLabel(), QString("Change adaptive sampling"));
    QVERIFY(document.scene().settings.render.adaptive.goal == AdaptiveGoal::Mean);
    document.undo();
    QVERIFY(document.scene().settings.render.adaptive.goal == AdaptiveGoal::Even);
    // A node's fields: a light's colour, a material's roughness.
    PropertiesPanel properties(document, false);
    document.setSelection({nodeNamed(document, "left_wall_red")});
    QCoreApplication::processEvents();
    auto* roughness = fieldNamed<QDoubleSpinBox>(properties, "Roughness");
    QVERIFY(roughness);
    roughness->setValue(0.25);
    QCOMPARE(lastLabel(), QString("Change roughness"));
    // Translated when shown, whatever the language was when the edit was made.
    Translations translations;
    QCOMPARE(translations.install(*QCoreApplication::instance(), "de"), QString("de"));
    QCOMPARE(commandLabel(document.history().label(document.history().index() - 1)), QString("Rauheit ändern"));
    translations.install(*QCoreApplication::instance(), "en");
}

// Scrolling the Scene tab with the wheel switched the combo boxes and sliders it passed over.
void PanelsTest::wheelScrollsThePanelNotTheFields() {
    Document document;
    QCOMPARE(document.open(cornellBox()), QString());
    PropertiesPanel scene(document, true);
    scene.resize(380, 300);
    scene.show();
    QVERIFY(QTest::qWaitForWindowExposed(&scene));
    auto* clipping = fieldNamed<QComboBox>(scene, "TAA history clipping");
    auto* blend = fieldNamed<FloatField>(scene, "TAA blend (current frame)");
    QVERIFY(clipping && blend);
    scene.ensureWidgetVisible(clipping);
    const int scrolled = scene.verticalScrollBar()->value();
    const auto wheel = [](QWidget* target) {
        const QPointF at(target->width() / 2.0, target->height() / 2.0);
        QWheelEvent event(at, target->mapToGlobal(at), QPoint(), QPoint(0, -120), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(target, &event);
    };
    const int index = clipping->currentIndex();
    wheel(clipping);
    wheel(blend->slider());
    wheel(blend->spinBox());
    QCOMPARE(clipping->currentIndex(), index);
    QCOMPARE(document.history().count(), std::size_t{0});
    QVERIFY(scene.verticalScrollBar()->value() > scrolled); // the panel scrolled instead
    // Clicked into, a field takes the wheel.
    clipping->setFocus();
    QTRY_VERIFY(clipping->hasFocus());
    wheel(clipping);
    QVERIFY(clipping->currentIndex() != index);
    QCOMPARE(document.history().count(), std::size_t{1});
}

void PanelsTest::sliderDragIsOneUndoStep() {
    Document document;
    QCOMPARE(document.open(cornellBox()), QString());
    PropertiesPanel panel(document, false);
    document.setSelection({nodeNamed(document, "left_wall_red")});
    QCoreApplication::processEvents();
    auto* roughness = fieldNamed<FloatField>(panel, "Roughness");
    QVERIFY(roughness);
    const float original = materialNamed(document, "red").roughnessFactor;
    QSlider* slider = roughness->slider();
    slider->setSliderDown(true); // what a mouse press on the handle does
    for (int position : {100, 300, 600, 900}) slider->setValue(position);
    slider->setSliderDown(false);
    QCOMPARE(document.history().count(), std::size_t{1});
    QCOMPARE(materialNamed(document, "red").roughnessFactor, 0.9f);
    QCOMPARE(roughness->spinBox()->value(), 0.9);
    // A second drag is a second step.
    slider->setSliderDown(true);
    slider->setValue(200);
    slider->setSliderDown(false);
    QCOMPARE(document.history().count(), std::size_t{2});
    document.undo();
    document.undo();
    QCOMPARE(materialNamed(document, "red").roughnessFactor, original);
    QCOMPARE(roughness->spinBox()->value(), double(original));
}

// Two of three spheres selected: a radius slider drag changes both (one undo step per drag, as
// with one node), Position X sets both, the third sphere is untouched; undo restores each.
void PanelsTest::aFieldChangedWithSeveralSelectedChangesAll() {
    Document document;
    std::vector<NodeId> spheres;
    for (int i = 0; i < 3; ++i) {
        QCOMPARE(addNode(document, QString("ball %1").arg(i), defaultShape(ShapeKind::Sphere)), QString());
        spheres.push_back(document.selection().front());
    }
    const auto radius = [&](int i) { return document.scene().at(spheres[std::size_t(i)]).get<Shape>()->radius; };
    const auto x = [&](int i) { return document.scene().at(spheres[std::size_t(i)]).local.translation.x; };
    const float radiusBefore = radius(2), xBefore = x(2);
    PropertiesPanel panel(document, false);
    document.setSelection({spheres[0], spheres[1]});
    QCoreApplication::processEvents();
    const std::size_t steps = document.history().index();
    auto* radiusField = fieldNamed<FloatField>(panel, "Radius (m)");
    QVERIFY(radiusField);
    QSlider* slider = radiusField->slider();
    slider->setSliderDown(true);
    for (int position : {100, 300, 500}) slider->setValue(position);
    slider->setSliderDown(false);
    QCOMPARE(document.history().index(), steps + 1);
    QVERIFY(radius(0) != radiusBefore);
    QCOMPARE(radius(1), radius(0));
    QCOMPARE(radius(2), radiusBefore);

    auto* positionX = fieldNamed<FloatField>(panel, "Position X");
    QVERIFY(positionX);
    positionX->spinBox()->setValue(2.5);
    QCOMPARE(document.history().index(), steps + 2);
    QCOMPARE(x(0), 2.5f);
    QCOMPARE(x(1), 2.5f);
    QCOMPARE(x(2), xBefore);
    document.undo();
    document.undo();
    QCOMPARE(radius(0), radiusBefore);
    QCOMPARE(radius(1), radiusBefore);
    QVERIFY(x(0) != 2.5f && x(1) != 2.5f);
}

void PanelsTest::historyPanelClickJumps() {
    Document document;
    QCOMPARE(document.open(cornellBox()), QString());
    HistoryPanel panel(document);
    PropertiesPanel properties(document, true);
    auto* exposure = fieldNamed<FloatField>(properties, "Exposure (EV)");
    QVERIFY(exposure);
    exposure->spinBox()->setValue(1.0);
    exposure->spinBox()->setValue(2.0);
    QCoreApplication::processEvents();
    QCOMPARE(panel.model().rowCount(), 3);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    const QRect rect = panel.view().visualRect(panel.model().index(1));
    QTest::mouseClick(panel.view().viewport(), Qt::LeftButton, {}, rect.center());
    QCOMPARE(document.history().index(), std::size_t{1});
    QCOMPARE(document.scene().settings.render.exposure, 1.0f);
    QCOMPARE(exposure->spinBox()->value(), 1.0); // the settings panel follows the jump
}

void PanelsTest::filterKeepsMatchesAndTheirParents() {
    Document document;
    QCOMPARE(document.open(cornellBox()), QString());
    OutlinerPanel panel(document);
    panel.filter().setText("WALL");
    QCOMPARE(panel.view().model()->rowCount(), 3);
    panel.filter().clear();
    QCOMPARE(panel.view().model()->rowCount(), 9);
}

QTEST_MAIN(PanelsTest)
#include "panels_test.moc"
