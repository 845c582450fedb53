// The Materials panel in the real window (Xvfb): swatches rendered by the path tracer, a material
// from a preset assigned by the panel's button and by a drop on the outliner, turned red and seen
// red in the path-traced view, a texture file loaded into base colour and seen in the view, undo of
// each step, and save -> reopen giving the same document with the texture copied beside the scene.
#include "editor_fixtures.h"
#include "window_options.h"
#include "test_viewport_scene.h"

#include "editor/document/edit_operations.h"
#include "editor/document/scene_templates.h"
#include "editor/main_window/main_window.h"
#include "editor/materials/material_list_model.h"
#include "editor/materials/material_operations.h"
#include "editor/materials/material_presets.h"
#include "editor/materials/materials_panel.h"
#include "editor/materials/swatch_renderer.h"
#include "editor/outliner/outliner_model.h"
#include "editor/outliner/outliner_panel.h"
#include "editor/viewport/render_view.h"
#include "editor/viewport/viewport.h"
#include "editor/properties/properties_panel.h"
#include "editor/properties/property_form.h"
#include "scene/history/asset_commands.h"
#include "scene/history/node_commands.h"
#include "scene/history/set_node_field.h"
#include "scene/geometry/geometry.h"

#include <QAction>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QListView>
#include <QMimeData>
#include <QPushButton>
#include <QSortFilterProxyModel>
#include <QTemporaryDir>
#include <QToolButton>
#include <QTreeView>
#include <QtTest>

#include <filesystem>

using namespace glint;
using namespace glint::editor;

namespace {



} // namespace

class TestMaterialsPanel : public QObject {
    Q_OBJECT
    QTemporaryDir temp_;

private slots:
    void initTestCase() { QVERIFY(temp_.isValid()); }

    // The forms wrap to the dock's width: a mesh whose textures have long names (the WaterBottle's,
    // such as "WaterBottle_occlusionRoughnessMetallic") still shows every number field of its
    // transform inside the panel, where the texture combos once pushed them out of view.
    void longTextureNamesKeepTheFieldsInView() {
        MainWindow window(glint::editor::test::windowOptions(temp_.filePath("autosave-long-names")));
        window.resize(1280, 720);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.openFile(QStringLiteral(GLINT_RESOURCES_DIR "/scenes/water_bottle/WaterBottle.gltf")));
        QTRY_VERIFY_WITH_TIMEOUT(!window.document().scene().nodes().empty(), 30000);
        window.document().setSelection({window.document().scene().nodes().begin()->first});
        // The node's panel is the one whose texture slots list the bottle's images (the Scene tab has another).
        const auto nodePanel = [&]() -> PropertiesPanel* {
            for (PropertiesPanel* candidate : window.findChildren<PropertiesPanel*>())
                for (const QComboBox* combo : candidate->widget()->findChildren<QComboBox*>())
                    if (combo->findText(QStringLiteral("WaterBottle_occlusionRoughnessMetallic"), Qt::MatchContains) >= 0) return candidate;
            return nullptr;
        };
        QTRY_VERIFY_WITH_TIMEOUT(nodePanel(), 30000);
        PropertiesPanel* panel = nodePanel();
        auto* dock = qobject_cast<QDockWidget*>(panel->parentWidget());
        QVERIFY(dock);
        window.resizeDocks({dock}, {320}, Qt::Horizontal); // the panel's width on a 1600-px screen
        QTest::qWait(50); // the layout settles
        const int visible = panel->viewport()->width();
        qInfo("panel viewport %d px, form %d px", visible, panel->widget()->width());
        for (const QDoubleSpinBox* field : panel->widget()->findChildren<QDoubleSpinBox*>()) {
            const int right = field->mapTo(panel->viewport(), QPoint(field->width(), 0)).x();
            QVERIFY2(right <= visible, qPrintable(QStringLiteral("%1 ends at %2 of %3 px").arg(field->objectName()).arg(right).arg(visible)));
        }
    }

    // Each swatch is rendered once per look: a red plastic sphere is red at its centre and grey-lit
    // at its rim, the copy of a material (same content) reuses its swatch, and an edit renders anew.
    void swatchesAreRenderedByThePathTracer() {
        Document document;
        Scene scene;
        Material red = findMaterialPreset("plastic")->value;
        red.baseColorFactor = {0.8f, 0.02f, 0.02f, 1.0f};
        const MaterialId redId = scene.materials.add(red);
        scene.materials.add(findMaterialPreset("gold")->value);
        scene.materials.add(findMaterialPreset("glass")->value);
        document.newScene(scene);
        MaterialsPanel panel(document);
        SwatchRenderer& swatches = *panel.swatches();
        QTRY_VERIFY_WITH_TIMEOUT(swatches.rendered() == 3 && !swatches.busy(), 120000);
        QVERIFY2(swatches.error().isEmpty(), qPrintable(swatches.error()));
        QVERIFY2(swatches.lastFailure().isEmpty(), qPrintable(swatches.lastFailure()));
        for (int row = 0; row < 3; ++row) {
            const QPixmap pixmap = panel.model().index(row).data(Qt::DecorationRole).value<QPixmap>();
            QCOMPARE(pixmap.size(), QSize(SwatchRenderer::kSize, SwatchRenderer::kSize));
            pixmap.save(QStringLiteral(GLINT_TEST_OUTPUT_DIR "/material_swatch_%1.png").arg(row));
        }
        const QImage redSwatch = swatches.cached(SwatchRenderer::contentHash(document.scene(), redId));
        const glm::dvec3 centre = glint::test::meanRgbAround(redSwatch, {24, 24}, 3);
        qInfo("red swatch centre (%.0f %.0f %.0f); first swatch (context, compilation) %.1f ms", centre.x, centre.y, centre.z,
              swatches.firstRenderMs());
        QVERIFY(centre.x > 60.0 && centre.x > 2.5 * centre.y && centre.x > 2.5 * centre.z);

        MaterialId copy;
        QCOMPARE(duplicateMaterial(document, redId, &copy), QString());
        QCOMPARE(panel.model().rowCount(), 4);
        QVERIFY(!panel.model().indexOf(copy).data(Qt::DecorationRole).isNull()); // cached: no render
        QVERIFY(!swatches.busy());
        QCOMPARE(swatches.rendered(), 3);

        // Timing: the same scene rendered again (the programs compiled) is the steady cost.
        Material blue = document.scene().materials.at(copy);
        blue.baseColorFactor = {0.02f, 0.02f, 0.8f, 1.0f};
        document.push(std::make_unique<SetMaterial>(copy, blue));
        QTRY_VERIFY_WITH_TIMEOUT(swatches.rendered() == 4 && !swatches.busy(), 60000);
        const QImage blueSwatch = panel.model().indexOf(copy).data(Qt::DecorationRole).value<QPixmap>().toImage();
        const glm::dvec3 b = glint::test::meanRgbAround(blueSwatch, {24, 24}, 3);
        QVERIFY(b.z > 2.5 * b.x);
        qInfo("swatch render (48x48, 16 spp, compiled programs): %.1f ms", swatches.lastRenderMs());

        // Deterministic: another renderer (its own context) gives the same pixels.
        SwatchRenderer again;
        again.request(document.scene(), redId);
        QTRY_VERIFY_WITH_TIMEOUT(again.rendered() == 1 && !again.busy(), 60000);
        QCOMPARE(again.cached(SwatchRenderer::contentHash(document.scene(), redId)), redSwatch);

        // A texture file in base colour shows on the swatch (white factor x blue texture).
        QImage blueImage(8, 8, QImage::Format_RGB32);
        blueImage.fill(qRgb(20, 40, 235));
        QVERIFY(blueImage.save(temp_.filePath("swatch blue.png")));
        Material white = document.scene().materials.at(redId);
        white.baseColorFactor = glm::vec4(1.0f);
        document.push(std::make_unique<SetMaterial>(redId, white));
        QCOMPARE(loadTextureFile(document, redId, *findTextureSlot("baseColor"), temp_.filePath("swatch blue.png")), QString());
        const std::uint64_t texturedHash = SwatchRenderer::contentHash(document.scene(), redId);
        QTRY_VERIFY_WITH_TIMEOUT(!swatches.cached(texturedHash).isNull(), 60000);
        const glm::dvec3 t = glint::test::meanRgbAround(swatches.cached(texturedHash), {24, 24}, 3);
        qInfo("textured swatch centre (%.0f %.0f %.0f)", t.x, t.y, t.z);
        QVERIFY(t.z > 2.0 * t.x && t.z > 60.0);
    }

    // The whole loop in the window: Studio, a sphere, New > Plastic, Assign to selection, a Metal
    // dropped on the sphere in the outliner, the colour turned red (red in the view), a texture file
    // loaded into base colour (its colour in the view), undo of each step, save -> reopen.
    void aMaterialFromThePanelRendersOnTheSphere() {
        MainWindow window(glint::editor::test::windowOptions(temp_.filePath("autosave-panel")));
        window.resize(1100, 700);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.viewport());
        RenderView& view = window.viewport()->view();
        window.findChild<QAction*>(templateActionId(SceneTemplate::Studio))->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(view.stats().samples >= 1 && !view.stats().preparing, 60000);
        Document& document = window.document();
        QCOMPARE(addNode(document, "Sphere", defaultShape(ShapeKind::Sphere)), QString());
        const NodeId sphere = document.selection().front();
        const MaterialId own = document.scene().at(sphere).get<Shape>()->material;
        MaterialsPanel& panel = window.materials();
        auto materialOfSphere = [&] { return document.scene().at(sphere).get<Shape>()->material; };

        // New > Plastic: a material of plain glTF values, selected in the list.
        const Scene beforeNew = document.scene();
        QAction* plastic = panel.findChild<QAction*>("materials.new.plastic");
        QVERIFY(plastic);
        plastic->trigger();
        const MaterialId plasticId = panel.currentMaterial();
        QVERIFY(plasticId.valid() && plasticId != own);
        QCOMPARE(document.scene().materials.at(plasticId).roughnessFactor, findMaterialPreset("plastic")->value.roughnessFactor);
        QCOMPARE(document.scene().materials.at(plasticId).name, std::string("Plastic"));

        // Assign to selection (the button), one undo step; undo gives the sphere its own back.
        const Scene beforeAssign = document.scene();
        auto* assign = panel.findChild<QToolButton*>("materials.assign");
        QVERIFY(assign && assign->isEnabled());
        QTest::mouseClick(assign, Qt::LeftButton);
        QCOMPARE(materialOfSphere(), plasticId);
        QCOMPARE(panel.model().usersOf(plasticId), 1);
        document.undo();
        QVERIFY(document.scene() == beforeAssign);
        document.redo();
        QCOMPARE(materialOfSphere(), plasticId);

        // Metal dragged from the list onto the sphere's row in the outliner.
        panel.findChild<QAction*>("materials.new.metal")->trigger();
        const MaterialId metal = panel.currentMaterial();
        const Scene beforeDrop = document.scene();
        QTreeView& tree = window.outliner().view();
        auto* proxy = qobject_cast<QSortFilterProxyModel*>(tree.model());
        QVERIFY(proxy);
        const QModelIndex row = proxy->mapFromSource(window.outliner().model().indexOf(sphere));
        tree.scrollTo(row);
        const QPoint at = tree.visualRect(row).center();
        std::unique_ptr<QMimeData> mime(panel.model().mimeData({panel.model().indexOf(metal)}));
        const Qt::DropActions actions = Qt::CopyAction | Qt::LinkAction;
        QDragEnterEvent enter(at, actions, mime.get(), Qt::LeftButton, Qt::NoModifier);
        QCoreApplication::sendEvent(tree.viewport(), &enter);
        QDragMoveEvent move(at, actions, mime.get(), Qt::LeftButton, Qt::NoModifier);
        QCoreApplication::sendEvent(tree.viewport(), &move);
        QVERIFY(move.isAccepted());
        QDropEvent drop(at, actions, mime.get(), Qt::LeftButton, Qt::NoModifier);
        QCoreApplication::sendEvent(tree.viewport(), &drop);
        QTRY_COMPARE(materialOfSphere(), metal);
        document.undo();
        QVERIFY(document.scene() == beforeDrop);
        QCOMPARE(materialOfSphere(), plasticId);

        // The sphere's centre in the view, with nothing selected (no gizmo over it).
        document.setSelection({sphere});
        const auto centre = view.project(glm::dvec3(document.scene().worldFromNode(sphere)[3]));
        QVERIFY(centre);

        // Metal dropped on the sphere in the viewport (the window takes drops the view passes on),
        // once the picker knows the sphere; a drop on empty sky is refused.
        {
            const Scene beforeViewDrop = document.scene();
            QTRY_COMPARE_WITH_TIMEOUT(view.pickAt(*centre), sphere, 30000);
            const QPoint inWindow = view.mapTo(&window, centre->toPoint());
            QDragEnterEvent viewEnter(inWindow, actions, mime.get(), Qt::LeftButton, Qt::NoModifier);
            QCoreApplication::sendEvent(&window, &viewEnter);
            QVERIFY(viewEnter.isAccepted());
            QDragMoveEvent viewMove(inWindow, actions, mime.get(), Qt::LeftButton, Qt::NoModifier);
            QCoreApplication::sendEvent(&window, &viewMove);
            QVERIFY(viewMove.isAccepted());
            QDropEvent viewDrop(inWindow, actions, mime.get(), Qt::LeftButton, Qt::NoModifier);
            QCoreApplication::sendEvent(&window, &viewDrop);
            QCOMPARE(materialOfSphere(), metal);
            document.undo();
            QVERIFY(document.scene() == beforeViewDrop);
            const QPoint sky = view.mapTo(&window, QPoint(view.width() / 2, 2));
            QVERIFY(!view.pickAt(QPointF(view.width() / 2, 2)).valid());
            QDragMoveEvent skyMove(sky, actions, mime.get(), Qt::LeftButton, Qt::NoModifier);
            QCoreApplication::sendEvent(&window, &skyMove);
            QVERIFY(!skyMove.isAccepted());
        }
        const qreal ratio = view.devicePixelRatioF();
        const QPoint pixel(int(centre->x() * ratio), int(centre->y() * ratio));
        // The edit's first frame on screen, then 8 samples of it: the mean colour at the centre.
        auto settle = [&](glm::dvec3& out, long long paints) {
            QTRY_VERIFY_WITH_TIMEOUT(view.stats().paints > paints + 1, 60000);
            QTRY_VERIFY_WITH_TIMEOUT(view.stats().samples >= 8 && !view.stats().preparing, 60000);
            out = glint::test::meanRgbAround(view.grabFramebuffer(), pixel, 2);
        };
        long long paints = view.stats().paints;

        // Base colour turned red in the property panel's colour field: red in the path-traced view.
        const Scene beforeRed = document.scene();
        auto* colour = glint::editor::test::fieldNamed<ColorField>(window.properties(), "Base colour");
        QVERIFY(colour);
        document.setSelection({});
        document.setSelection({sphere});
        colour = glint::editor::test::fieldNamed<ColorField>(window.properties(), "Base colour");
        QVERIFY(colour);
        paints = view.stats().paints;
        emit colour->edited(QColor(220, 10, 10));
        QVERIFY(document.scene().materials.at(plasticId).baseColorFactor.x > 0.5f);
        document.setSelection({});
        glm::dvec3 red;
        settle(red, paints);
        if (QTest::currentTestFailed()) return;
        qInfo("sphere centre red (%.0f %.0f %.0f)", red.x, red.y, red.z);
        QVERIFY(red.x > 2.0 * red.y && red.x > 2.0 * red.z && red.x > 40.0);
        paints = view.stats().paints;
        document.undo();
        QVERIFY(document.scene() == beforeRed);
        document.setSelection({});
        glm::dvec3 grey;
        settle(grey, paints);
        if (QTest::currentTestFailed()) return;
        QVERIFY(grey.x < 1.5 * grey.z);

        // A blue PNG loaded into base colour through the slot's Load button and its file dialog. The
        // renderer textures triangles, so the sphere becomes a uv-sphere mesh in the same place
        // (the shape hidden), given the material by the panel's button (one primitive).
        const NodeId ball = [&] {
            Mesh mesh;
            mesh.name = "Ball";
            mesh.primitives.push_back(tessellateShape(*document.scene().at(sphere).get<Shape>(), 48));
            document.beginMacro("Add ball");
            auto addMesh = std::make_unique<AddAsset<Mesh>>(std::move(mesh));
            AddAsset<Mesh>* rawMesh = addMesh.get();
            document.push(std::move(addMesh));
            Node node;
            node.name = "Ball";
            node.local = document.scene().at(sphere).local;
            node.component = MeshInstance{rawMesh->id()};
            auto addNode = std::make_unique<AddNode>(std::move(node));
            AddNode* rawNode = addNode.get();
            document.push(std::move(addNode));
            document.push(std::make_unique<SetVisibility>(sphere, false));
            document.endMacro();
            return rawNode->nodeId();
        }();
        const MeshId ballMesh = document.scene().at(ball).get<MeshInstance>()->mesh;
        panel.selectMaterial(plasticId);
        document.setSelection({ball});
        QTest::mouseClick(assign, Qt::LeftButton);
        QCOMPARE(document.scene().meshes.at(ballMesh).primitives.front().material, plasticId);
        QImage blueImage(8, 8, QImage::Format_RGB32);
        blueImage.fill(qRgb(20, 40, 235));
        const QString bluePng = temp_.filePath("blue tile.png");
        QVERIFY(blueImage.save(bluePng));
        auto* load = window.properties().findChild<QToolButton*>("texture.load.baseColor");
        QVERIFY(load);
        const Scene beforeTexture = document.scene();
        paints = view.stats().paints;
        QTest::mouseClick(load, Qt::LeftButton);
        QFileDialog* dialog = nullptr;
        QTRY_VERIFY((dialog = window.findChild<QFileDialog*>("materials.textureFileDialog")) != nullptr);
        dialog->selectFile(bluePng);
        static_cast<QDialog*>(dialog)->accept(); // as the Open button does
        const Material& textured = document.scene().materials.at(plasticId);
        QVERIFY(textured.baseColorTexture.valid());
        const Image& image = document.scene().images.at(document.scene().textures.at(textured.baseColorTexture.texture).image);
        QCOMPARE(image.uri, std::string("blue_tile.png"));
        document.setSelection({});
        glm::dvec3 blue;
        settle(blue, paints);
        if (QTest::currentTestFailed()) return;
        qInfo("ball centre textured (%.0f %.0f %.0f)", blue.x, blue.y, blue.z);
        QVERIFY(blue.z > 2.0 * blue.x && blue.z > 40.0);
        paints = view.stats().paints;
        document.undo();
        QVERIFY(document.scene() == beforeTexture);
        // Undo brings back the selection it was made with: clear it again, or the gizmo's handle
        // covers the centre where the window is large enough to show the view at full size.
        document.setSelection({});
        glm::dvec3 untextured;
        settle(untextured, paints);
        if (QTest::currentTestFailed()) return;
        qInfo("ball centre untextured (%.0f %.0f %.0f)", untextured.x, untextured.y, untextured.z);
        QVERIFY(untextured.z < 1.5 * untextured.x);
        document.redo();

        // Save -> reopen: the same document, the image beside the scene.
        const QString saved = temp_.filePath("materials/scene.gltf");
        QVERIFY(QDir().mkpath(temp_.filePath("materials")));
        QCOMPARE(document.saveAs(saved), QString());
        QVERIFY(QFile::exists(temp_.filePath("materials/blue_tile.png")));
        Document reopened;
        QCOMPARE(reopened.open(saved), QString());
        QVERIFY(reopened.scene().materials == document.scene().materials);
        QVERIFY(reopened.scene().textures == document.scene().textures);
        QVERIFY(reopened.scene().samplers == document.scene().samplers);
        QVERIFY(reopened.scene().images == document.scene().images);
        QCOMPARE(reopened.scene().at(sphere).component, document.scene().at(sphere).component);
        QCOMPARE(reopened.scene().at(ball).component, document.scene().at(ball).component);
        QCOMPARE(reopened.scene().meshes.at(ballMesh).primitives.front().material, plasticId);
        // A picture of the panel with its swatches, for people (beside editor_main_window.png).
        if (auto* dock = qobject_cast<QDockWidget*>(panel.parentWidget())) dock->raise();
        QTRY_VERIFY_WITH_TIMEOUT(panel.swatches() && !panel.swatches()->busy(), 60000);
        window.grab().save(QStringLiteral(GLINT_TEST_OUTPUT_DIR "/editor_materials_panel.png"));
        QCOMPARE(document.undo().flags != 0, true); // the history still undoes after the save
        Q_UNUSED(beforeNew);
    }
};

QTEST_MAIN(TestMaterialsPanel)
#include "test_materials_panel.moc"
