// Area lights in the editor: Add > Light > Area rectangle / disk / sphere through the outliner's
// Add menu lands above the view's focus facing down, sized to the scene, with the power that gives
// the focus the irradiance of a new point light; the property panel edits shape, size, radius,
// colour and power, each edit one undoable step.
#include "editor_fixtures.h"

#include "editor/document/edit_operations.h"
#include "editor/document/node_placement.h"
#include "editor/outliner/outliner_panel.h"
#include "editor/properties/properties_panel.h"
#include "editor/properties/property_form.h"

#include <QAction>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QMenu>

#include <cmath>
#include <numbers>

using namespace glint;
using namespace glint::editor;
using namespace glint::editor::test;

namespace {

const Light* currentLight(const Document& document) {
    const Node* node = document.scene().node(document.currentNode());
    return node ? node->get<Light>() : nullptr;
}

void settle() {
    QCoreApplication::processEvents();
    QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
}

} // namespace

class TestAreaLightPanel : public QObject {
    Q_OBJECT

private slots:
    // A scene of scale 4 m looked at around (1, 0, 2), 3 m of free space above it: shapes get 1 m,
    // so the rectangle is 1 m square, 2.4 m up (0.6 x scale), its -Z straight down, and its power
    // gives the point below Blender's point-light irradiance (closed form, within 1e-4).
    void addMenuPlacesAreaLights() {
        Document document;
        document.setViewFocusProvider([] { return ViewFocus{{1.0, 0.0, 2.0}, 4.0, 3.0, 1e30}; });
        OutlinerPanel outliner(document);
        const double expected = newLightIrradiance();
        for (const QString& name : {QString("Area rectangle"), QString("Area disk"), QString("Area sphere")}) {
            QAction* add = actionNamed(outliner.addMenu(), name);
            QVERIFY2(add, qPrintable(name));
            add->trigger();
            settle();
            const Light* light = currentLight(document);
            QVERIFY2(light && light->type == LightType::Area, qPrintable(name));
            const Node& node = document.scene().at(document.currentNode());
            const glm::vec3 shines = glm::mat3(document.scene().worldFromNode(node.id)) * glm::vec3(0.0f, 0.0f, -1.0f);
            QVERIFY(glm::length(shines - glm::vec3(0.0f, -1.0f, 0.0f)) < 1e-5f);
            const glm::vec3 at = node.local.translation;
            QCOMPARE(at.x, 1.0f);
            QCOMPARE(at.z, 2.0f);
            double irradiance = 0.0;
            const double h = at.y;
            if (light->areaShape == AreaShape::Rectangle) {
                QCOMPARE(light->size, glm::vec2(1.0f));
                QVERIFY(std::abs(h - 2.4) < 1e-5);
                const double x = 0.5 / h, sx = std::sqrt(1.0 + x * x);
                irradiance = light->intensity / (std::numbers::pi * 1.0) * 4.0 * (2.0 * x / sx * std::atan(x / sx)) / 2.0;
            } else if (light->areaShape == AreaShape::Disk) {
                QCOMPARE(light->size.x, 1.0f);
                irradiance = light->intensity / (std::numbers::pi * std::numbers::pi * 0.25) * std::numbers::pi * 0.25 / (h * h + 0.25);
            } else {
                QCOMPARE(light->radius, 0.1f);
                irradiance = light->intensity / (4.0 * std::numbers::pi * h * h);
            }
            QVERIFY2(std::abs(irradiance / expected - 1.0) < 1e-4, qPrintable(QString("%1: %2 vs %3 W/m^2").arg(name).arg(irradiance).arg(expected)));
        }
        QCOMPARE(document.history().count(), std::size_t{3});
    }

    // The panel shows an area light's fields by shape; power, sizes and shape are undoable edits.
    void panelEditsAreUndoable() {
        Document document;
        QCOMPARE(addNode(document, "area", defaultAreaLight(AreaShape::Rectangle)), QString());
        PropertiesPanel panel(document, false);
        settle();
        const Light initial = *currentLight(document); // placed: sized and powered for the view
        QCOMPARE(initial.radius, 0.0f);
        const auto shown = [&](const QString& name) { return fieldNamed<QDoubleSpinBox>(panel, name) != nullptr; };
        QVERIFY(shown("Power (W)") && shown("Size X (m)") && shown("Size Y (m)") && !shown("Diameter (m)"));
        QVERIFY(!shown("Range (m, 0 = infinite)"));
        const std::size_t before = document.history().count();
        fieldNamed<QDoubleSpinBox>(panel, "Power (W)")->setValue(250.0);
        QCOMPARE(currentLight(document)->intensity, 250.0f);
        fieldNamed<QDoubleSpinBox>(panel, "Size Y (m)")->setValue(0.5);
        QCOMPARE(currentLight(document)->size, glm::vec2(initial.size.x, 0.5f));
        QCOMPARE(document.history().count(), before + 2);
        auto* shape = fieldNamed<QComboBox>(panel, "Shape");
        QVERIFY(shape);
        shape->setCurrentIndex(int(AreaShape::Disk));
        emit shape->activated(int(AreaShape::Disk));
        settle();
        QCOMPARE(currentLight(document)->areaShape, AreaShape::Disk);
        QVERIFY(shown("Diameter (m)") && !shown("Size X (m)"));
        fieldNamed<QDoubleSpinBox>(panel, "Diameter (m)")->setValue(2.0);
        QCOMPARE(currentLight(document)->size, glm::vec2(2.0f));
        shape = fieldNamed<QComboBox>(panel, "Shape");
        shape->setCurrentIndex(int(AreaShape::Sphere));
        emit shape->activated(int(AreaShape::Sphere));
        settle();
        QVERIFY(shown("Radius (m)") && !shown("Diameter (m)"));
        QCOMPARE(currentLight(document)->radius, 1.0f); // half the disk's diameter
        QCOMPARE(document.history().count(), before + 5);
        for (int i = 0; i < 5; ++i) document.undo();
        settle();
        QVERIFY(currentLight(document) && *currentLight(document) == initial);
        QVERIFY(shown("Size X (m)"));
        // A point light made an area light keeps no cone or range (what the file would drop).
        Light spot;
        spot.type = LightType::Spot;
        spot.range = 5.0f;
        spot.innerConeAngle = 0.3f;
        QCOMPARE(addNode(document, "spot", spot), QString());
        settle();
        auto* type = fieldNamed<QComboBox>(panel, "Type");
        QVERIFY(type);
        type->setCurrentIndex(int(LightType::Area));
        emit type->activated(int(LightType::Area));
        settle();
        QCOMPARE(currentLight(document)->type, LightType::Area);
        QCOMPARE(currentLight(document)->range, 0.0f);
        QCOMPARE(currentLight(document)->innerConeAngle, 0.0f);
        QVERIFY(shown("Power (W)"));
    }
};

QTEST_MAIN(TestAreaLightPanel)
#include "test_area_light_panel.moc"
