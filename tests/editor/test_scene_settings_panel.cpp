// The scene settings panel (offscreen, no GL): in the real-time reconstruction section a slider
// drag is one undo step, undo restores the default exactly, and the values reach the saved project
// file; the active camera and the frame rate are chosen there too, and the fog is edited and undone.
#include "editor_fixtures.h"

#include "editor/history_view/command_labels.h"
#include "editor/properties/properties_panel.h"
#include "editor/properties/property_form.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QFile>
#include <QGroupBox>
#include <QSlider>
#include <QSpinBox>
#include <QTemporaryDir>

#include <cmath>

using namespace glint;
using namespace glint::editor;
using namespace glint::editor::test;

class TestSceneSettingsPanel : public QObject {
    Q_OBJECT
private slots:
    void sliderDragIsOneUndoStep() {
        Document document;
        QCOMPARE(document.open(cornellBox()), QString());
        PropertiesPanel panel(document, true);
        auto* blend = fieldNamed<FloatField>(panel, "TAA blend (current frame)");
        QVERIFY(blend);
        QSlider* slider = blend->slider();
        slider->setSliderDown(true); // a mouse press on the handle
        for (int position : {100, 400, 700, 1000}) slider->setValue(position);
        slider->setSliderDown(false);
        QCOMPARE(document.history().count(), std::size_t{1});
        QCOMPARE(document.scene().settings.render.taa.blend, 1.0f);
        document.undo();
        QCOMPARE(document.scene().settings.render.taa.blend, TaaParameters{}.blend);
        QVERIFY(std::abs(blend->spinBox()->value() - double(TaaParameters{}.blend)) < 1e-6); // 3 decimals shown
        QVERIFY(!document.isModified()); // back at the clean state
    }

    void iterationsReachTheProjectFile() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        Document document;
        QCOMPARE(document.open(cornellBox()), QString());
        PropertiesPanel panel(document, true);
        auto* iterations = fieldNamed<QSpinBox>(panel, "SVGF a-trous iterations");
        QVERIFY(iterations);
        QCOMPARE(iterations->value(), 5);
        iterations->setValue(2);
        QCOMPARE(document.scene().settings.render.svgf.iterations, 2);
        QCOMPARE(document.history().count(), std::size_t{1});
        const QString scene = dir.filePath("box.gltf");
        QCOMPARE(document.saveAs(scene), QString());
        QFile project(dir.filePath("box.glint.json"));
        QVERIFY(project.open(QIODevice::ReadOnly));
        const QByteArray text = project.readAll();
        QVERIFY2(text.contains("\"svgf\": {\n      \"iterations\": 2\n    }"), text.constData());
        QVERIFY2(!text.contains("\"taa\""), text.constData()); // untouched: not written
        document.undo();
        QCOMPARE(iterations->value(), 5);
    }

    // Save As into another folder takes the environment image along, as the command line's
    // convert does: the saved scene renders with the same sky.
    void saveAsCarriesTheEnvironment() {
        QTemporaryDir from, to;
        QVERIFY(from.isValid() && to.isValid());
        const QString hdr = QStringLiteral(GLINT_RESOURCES_DIR "/env/studio_small_03_1k.hdr");
        QVERIFY(QFile::copy(hdr, from.filePath("sky.hdr")));
        {
            Document original;
            QCOMPARE(original.open(cornellBox()), QString());
            original.scene().settings.environment.file = "sky.hdr";
            QCOMPARE(original.saveAs(from.filePath("box.gltf")), QString());
        }
        Document document;
        QCOMPARE(document.open(from.filePath("box.gltf")), QString());
        QCOMPARE(document.saveAs(to.filePath("box.gltf")), QString());
        QVERIFY2(document.lastWarnings().isEmpty(), qPrintable(document.lastWarnings().join('\n')));
        QFile original(hdr), copy(to.filePath("sky.hdr"));
        QVERIFY(original.open(QIODevice::ReadOnly) && copy.open(QIODevice::ReadOnly));
        QCOMPARE(copy.readAll(), original.readAll());
    }

    void activeCameraAndFrameRate() {
        Document document;
        QCOMPARE(document.open(cornellBox()), QString());
        PropertiesPanel panel(document, true);
        auto* camera = fieldNamed<QComboBox>(panel, "Active camera");
        QVERIFY(camera);
        // "(the first camera)" plus one entry per camera node, in outliner order.
        int cameras = 0;
        for (const NodeId id : document.scene().depthFirst()) cameras += document.scene().at(id).get<Camera>() != nullptr;
        QVERIFY(cameras >= 1);
        QCOMPARE(camera->count(), 1 + cameras);
        emit camera->activated(1);
        const NodeId chosen{camera->itemData(1).toUInt()};
        QCOMPARE(document.scene().settings.activeCamera, chosen);
        QVERIFY(document.scene().at(chosen).get<Camera>());

        auto* fps = fieldNamed<QLineEdit>(panel, "Frames per second");
        QVERIFY(fps);
        QCOMPARE(fps->text(), QString("24"));
        fps->setText("24000/1001");
        emit fps->editingFinished();
        QCOMPARE(document.scene().settings.timeline.fpsNumerator, 24000);
        QCOMPARE(document.scene().settings.timeline.fpsDenominator, 1001);
        fps->setText("0/1"); // refused: nothing changes, no undo step
        emit fps->editingFinished();
        QCOMPARE(document.scene().settings.timeline.fpsNumerator, 24000);
        QCOMPARE(document.history().count(), std::size_t{2});
        document.undo();
        document.undo();
        QVERIFY(!document.isModified());
        QCOMPARE(camera->currentIndex(), 0);
    }

    // The Fog section: after Environment, each field one undo step named "Change fog", typed
    // values held to what the project file accepts, and the fog saved with the project.
    void fogIsEditedUndoneAndSaved() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        Document document;
        QCOMPARE(document.open(cornellBox()), QString());
        PropertiesPanel panel(document, true);
        const QList<QGroupBox*> sections = panel.findChildren<QGroupBox*>(); // in the panel's order
        const auto position = [&](const QString& title) {
            for (qsizetype i = 0; i < sections.size(); ++i)
                if (sections[i]->title() == title) return i;
            return qsizetype(-1);
        };
        QVERIFY(position("Environment") >= 0);
        QCOMPARE(position("Fog"), position("Environment") + 1);

        auto* density = fieldNamed<QDoubleSpinBox>(panel, "Density (1/m)");
        QVERIFY(density);
        QCOMPARE(density->value(), 0.0);
        density->setValue(0.05);
        QCOMPARE(document.scene().settings.fog.density, 0.05f);
        QCOMPARE(document.history().count(), std::size_t{1});
        const auto lastLabel = [&] { return commandLabel(document.history().label(document.history().index() - 1)); };
        QCOMPARE(lastLabel(), QString("Change fog"));
        QVERIFY(document.isModified());
        document.undo();
        QCOMPARE(document.scene().settings.fog.density, 0.0f);
        QCOMPARE(density->value(), 0.0); // the field follows the undo
        QCOMPARE(commandLabel(document.history().label(document.history().index())), QString("Change fog")); // the redo step
        QVERIFY(!document.isModified());
        QVERIFY(document.scene().settings.fog == Fog{});

        // Typed past the range: held to it (a negative density is no edit at all).
        auto* anisotropy = fieldNamed<QDoubleSpinBox>(panel, "Anisotropy");
        QVERIFY(anisotropy);
        anisotropy->setValue(1.5);
        QCOMPARE(document.scene().settings.fog.anisotropy, 0.99f);
        density->setValue(-1.0);
        QCOMPARE(document.scene().settings.fog.density, 0.0f);
        fieldNamed<QDoubleSpinBox>(panel, "Height falloff (1/m)")->setValue(0.5);
        fieldNamed<QDoubleSpinBox>(panel, "Base height (m)")->setValue(-2.0);
        density->setValue(0.1);
        const Fog edited = document.scene().settings.fog;
        QCOMPARE(edited.heightFalloff, 0.5f);
        QCOMPARE(edited.baseHeight, -2.0f);

        QCOMPARE(document.saveAs(dir.filePath("box.gltf")), QString());
        Document reopened;
        QCOMPARE(reopened.open(dir.filePath("box.gltf")), QString());
        QVERIFY(reopened.scene().settings.fog == edited);
    }
};

QTEST_MAIN(TestSceneSettingsPanel)
#include "test_scene_settings_panel.moc"
