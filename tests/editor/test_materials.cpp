// The material edits and the Materials panel's model over a real document (offscreen, no GL): the
// list model under QAbstractItemModelTester through new, duplicate, rename, delete unused, assign
// and undo; assignment to many nodes (shapes and a two-primitive mesh) in one undo step; textures
// from PNG and HDR files, and missing or broken files named in the error with nothing changed.
#include "editor_fixtures.h"

#include "editor/materials/material_list_model.h"
#include "editor/materials/material_operations.h"
#include "editor/materials/material_presets.h"
#include "editor/materials/materials_panel.h"
#include "editor/outliner/outliner_model.h"
#include "editor/properties/properties_panel.h"
#include "editor/properties/property_form.h"

#include <QAbstractItemModelTester>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QToolButton>
#include <QImage>
#include <QLineEdit>
#include <QListView>
#include <QMimeData>
#include <QSortFilterProxyModel>
#include <QTemporaryDir>
#include <QtTest>

#include <memory>

using namespace glint;
using namespace glint::editor;

namespace {

Mesh twoTriangleMesh(MaterialId first, MaterialId second) {
    Mesh mesh;
    mesh.name = "pair";
    for (const MaterialId material : {first, second}) {
        Primitive p;
        p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
        p.indices = {0, 1, 2};
        p.material = material;
        mesh.primitives.push_back(std::move(p));
    }
    return mesh;
}

struct Sample {
    Scene scene;
    NodeId ball, box, pair, lamp;
    MaterialId grey, blue;
    MeshId mesh;
};

Sample sample() {
    Sample s;
    Material grey;
    grey.name = "grey";
    s.grey = s.scene.materials.add(grey);
    Material blue;
    blue.name = "blue";
    blue.baseColorFactor = {0.1f, 0.1f, 0.9f, 1.0f};
    s.blue = s.scene.materials.add(blue);
    Node ball;
    ball.name = "ball";
    ball.component = Shape{.kind = ShapeKind::Sphere, .material = s.grey};
    s.ball = s.scene.addNode(ball);
    Node box;
    box.name = "box";
    box.component = Shape{.kind = ShapeKind::Box, .material = s.grey};
    s.box = s.scene.addNode(box);
    s.mesh = s.scene.meshes.add(twoTriangleMesh(s.grey, s.blue));
    Node pair;
    pair.name = "pair";
    pair.component = MeshInstance{s.mesh};
    s.pair = s.scene.addNode(pair);
    Node lamp;
    lamp.name = "lamp";
    lamp.component = Light{};
    s.lamp = s.scene.addNode(lamp);
    return s;
}

MaterialId shapeMaterial(const Document& d, NodeId node) { return d.scene().at(node).get<Shape>()->material; }

} // namespace

class TestMaterials : public QObject {
    Q_OBJECT
    QTemporaryDir temp_;

    // A 4x4 PNG, red and green checks, written by the test.
    QString checkerPng() {
        QImage image(4, 4, QImage::Format_RGB32);
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x) image.setPixel(x, y, (x + y) % 2 ? qRgb(255, 0, 0) : qRgb(0, 255, 0));
        const QString path = temp_.filePath("checker.png");
        if (!QFile::exists(path)) image.save(path);
        return path;
    }

private slots:
    void initTestCase() { QVERIFY(temp_.isValid()); }

    void listFollowsEveryMaterialEdit() {
        Document document;
        const Sample s = sample();
        document.newScene(s.scene);
        MaterialListModel model(document, nullptr);
        QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
        QCOMPARE(model.rowCount(), 2);
        QCOMPARE(model.index(0).data(MaterialListModel::NameRole).toString(), QString("grey"));
        QCOMPARE(model.index(0).data(MaterialListModel::UsersRole).toInt(), 3); // ball, box, pair
        QCOMPARE(model.index(1).data(MaterialListModel::UsersRole).toInt(), 1); // pair's second primitive
        QVERIFY(model.index(0).data().toString().contains("3 users"));

        // New from a preset: plain glTF values, a unique name.
        const MaterialPreset* glass = findMaterialPreset("glass");
        QVERIFY(glass);
        MaterialId added;
        QCOMPARE(newMaterial(document, glass->value, &added), QString());
        QCOMPARE(model.rowCount(), 3);
        QCOMPARE(document.scene().materials.at(added).transmissionFactor, 1.0f);
        QCOMPARE(model.index(2).data(MaterialListModel::UsersRole).toInt(), 0);
        QCOMPARE(document.history().label(document.history().index() - 1), std::string("New material"));
        MaterialId copy;
        QCOMPARE(duplicateMaterial(document, added, &copy), QString());
        QCOMPARE(document.scene().materials.at(copy).name, std::string("Glass.001"));
        QVERIFY(document.scene().materials.at(copy).ior == document.scene().materials.at(added).ior);

        // Rename through the model (the list's editor), refused when empty.
        QVERIFY(model.setData(model.indexOf(copy), "Bottle"));
        QCOMPARE(document.scene().materials.at(copy).name, std::string("Bottle"));
        QVERIFY(!model.setData(model.indexOf(copy), "  "));
        QVERIFY(model.setData(model.indexOf(copy), "grey")); // taken: made unique
        QCOMPARE(document.scene().materials.at(copy).name, std::string("grey.001"));

        // Delete unused: the two new ones, one step; undo brings both back with their ids.
        int removed = 0;
        QCOMPARE(deleteUnusedMaterials(document, &removed), QString());
        QCOMPARE(removed, 2);
        QCOMPARE(model.rowCount(), 2);
        document.undo();
        QCOMPARE(model.rowCount(), 4);
        QVERIFY(document.scene().materials.contains(copy));

        // Drag data names the material.
        std::unique_ptr<QMimeData> data(model.mimeData({model.indexOf(s.blue)}));
        QCOMPARE(decodeMaterials(data.get()), std::vector<MaterialId>{s.blue});

        // The panel's search filters by name.
        MaterialsPanel panel(document, nullptr, false);
        panel.search().setText("GLA");
        QCOMPARE(panel.view().model()->rowCount(), 1);
        panel.search().clear();
        QCOMPARE(panel.view().model()->rowCount(), 4);
    }

    // Shapes and a two-primitive mesh selected with a light: one undo step assigns the material to
    // the ball, the box and both primitives; the light is left alone; undo restores every one.
    void assignToManyNodesIsOneStep() {
        Document document;
        const Sample s = sample();
        document.newScene(s.scene);
        MaterialId red;
        Material value = findMaterialPreset("plastic")->value;
        value.baseColorFactor = {0.8f, 0.02f, 0.02f, 1.0f};
        QCOMPARE(newMaterial(document, value, &red), QString());
        const Scene before = document.scene();
        const std::size_t steps = document.history().index();
        MaterialsPanel panel(document, nullptr, false);
        panel.selectMaterial(red);
        QCOMPARE(panel.currentMaterial(), red);
        document.setSelection({s.ball, s.box, s.pair, s.lamp});
        panel.assignToSelection();
        QCOMPARE(document.history().index(), steps + 1);
        QCOMPARE(shapeMaterial(document, s.ball), red);
        QCOMPARE(shapeMaterial(document, s.box), red);
        for (const Primitive& p : document.scene().meshes.at(s.mesh).primitives) QCOMPARE(p.material, red);
        QCOMPARE(panel.model().usersOf(red), 3);
        QCOMPARE(panel.model().usersOf(s.grey), 0);
        document.undo();
        QVERIFY(document.scene() == before);

        // One primitive of the mesh.
        QCOMPARE(assignPrimitiveMaterial(document, s.mesh, 1, red), QString());
        QCOMPARE(document.scene().meshes.at(s.mesh).primitives[0].material, s.grey);
        QCOMPARE(document.scene().meshes.at(s.mesh).primitives[1].material, red);

        // Only a light selected: said in words, nothing changes.
        const std::size_t now = document.history().index();
        QVERIFY(!assignMaterial(document, red, {s.lamp}).isEmpty());
        QCOMPARE(document.history().index(), now);
    }

    // A material dropped on a node in the outliner (through the model, as the view calls it).
    void outlinerDropAssigns() {
        Document document;
        const Sample s = sample();
        document.newScene(s.scene);
        OutlinerModel outliner(document);
        std::unique_ptr<QMimeData> data(encodeMaterials({s.blue}));
        QVERIFY(outliner.canDropMimeData(data.get(), Qt::CopyAction, -1, -1, outliner.indexOf(s.ball)));
        QVERIFY(!outliner.canDropMimeData(data.get(), Qt::CopyAction, -1, -1, outliner.indexOf(s.lamp)));
        QVERIFY(!outliner.canDropMimeData(data.get(), Qt::CopyAction, 0, 0, {})); // between rows
        QVERIFY(outliner.dropMimeData(data.get(), Qt::CopyAction, -1, -1, outliner.indexOf(s.ball)));
        QTRY_COMPARE(shapeMaterial(document, s.ball), s.blue);
        QCOMPARE(shapeMaterial(document, s.box), s.grey);
    }

    // PNG kept byte for byte; HDR converted to PNG; names de-duplicated; one undo step each.
    void texturesLoadFromFiles() {
        Document document;
        const Sample s = sample();
        document.newScene(s.scene);
        const TextureSlot* base = findTextureSlot("baseColor");
        QVERIFY(base);
        const Scene before = document.scene();
        QCOMPARE(loadTextureFile(document, s.grey, *base, checkerPng()), QString());
        const Material& grey = document.scene().materials.at(s.grey);
        const Texture& texture = document.scene().textures.at(grey.baseColorTexture.texture);
        const Image& image = document.scene().images.at(texture.image);
        QCOMPARE(image.uri, std::string("checker.png"));
        QCOMPARE(image.mimeType, std::string("image/png"));
        QCOMPARE(image.width, 4);
        QFile file(checkerPng());
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray bytes = file.readAll();
        QCOMPARE(QByteArray(reinterpret_cast<const char*>(image.encoded.data()), qsizetype(image.encoded.size())), bytes);
        QVERIFY(document.scene().samplers.contains(texture.sampler));
        // The same file again, into another slot: another image, another name.
        QCOMPARE(loadTextureFile(document, s.blue, *findTextureSlot("emissive"), checkerPng()), QString());
        const Material& blue = document.scene().materials.at(s.blue);
        const Texture& second = document.scene().textures.at(blue.emissiveTexture.texture);
        QCOMPARE(document.scene().images.at(second.image).uri, std::string("checker-1.png"));
        // Radiance HDR: decoded by OpenImageIO and stored as PNG.
        QCOMPARE(loadTextureFile(document, s.blue, *findTextureSlot("occlusion"),
                                 QStringLiteral(GLINT_TEST_DATA_DIR "/env/studio_small_03_1k.hdr")),
                 QString());
        const Texture& hdr = document.scene().textures.at(document.scene().materials.at(s.blue).occlusionTexture.texture);
        const Image& converted = document.scene().images.at(hdr.image);
        QCOMPARE(converted.uri, std::string("studio_small_03_1k.png"));
        QCOMPARE(converted.mimeType, std::string("image/png"));
        QCOMPARE(converted.width, 1024);
        QCOMPARE(QImage::fromData(converted.encoded.data(), int(converted.encoded.size())).width(), 1024);
        document.undo();
        document.undo();
        document.undo();
        QVERIFY(document.scene() == before);
    }

    // The property panel of a two-primitive mesh: one material row per primitive, each assignable,
    // Edit shows that primitive's material; a slot with a texture shows its UV set, sampler and
    // transform, and editing them is undoable (a texture without a sampler gets its own).
    void propertyPanelListsPrimitivesAndTextureFields() {
        Document document;
        Sample s = sample();
        document.newScene(s.scene);
        PropertiesPanel panel(document, false);
        document.setSelection({s.pair});
        auto* second = panel.findChild<QToolButton*>("primitive.edit.1");
        QVERIFY(second);
        auto* materialRow = glint::editor::test::fieldNamed<QWidget>(panel, "Primitive 2 (1 triangle)");
        QVERIFY(materialRow);
        auto* choice = materialRow->findChild<QComboBox*>();
        QVERIFY(choice);
        QCOMPARE(choice->currentText(), QString("blue"));
        // Assign grey to primitive 2 through its row.
        choice->setCurrentIndex(choice->findText("grey"));
        emit choice->activated(choice->currentIndex());
        QCOMPARE(document.scene().meshes.at(s.mesh).primitives[1].material, s.grey);
        document.undo();
        QCOMPARE(document.scene().meshes.at(s.mesh).primitives[1].material, s.blue);
        // Edit on primitive 2: the material form below is blue's.
        QTest::mouseClick(panel.findChild<QToolButton*>("primitive.edit.1"), Qt::LeftButton);
        QTRY_VERIFY(panel.findChild<QToolButton*>("primitive.edit.1") && panel.findChild<QToolButton*>("primitive.edit.1")->isChecked());
        QTRY_VERIFY(glint::editor::test::fieldNamed<QWidget>(panel, "Base colour") != nullptr);
        QVERIFY(glint::editor::test::fieldNamed<QWidget>(panel, "    Wrap U") == nullptr); // no texture yet

        // A texture in blue's base colour: its fields appear; Wrap U and Offset U are undoable edits.
        QCOMPARE(loadTextureFile(document, s.blue, *findTextureSlot("baseColor"), checkerPng()), QString());
        QTRY_VERIFY(glint::editor::test::fieldNamed<QComboBox>(panel, "    Wrap U") != nullptr);
        auto* wrap = glint::editor::test::fieldNamed<QComboBox>(panel, "    Wrap U");
        wrap->setCurrentIndex(1);
        emit wrap->activated(1);
        const TextureId texture = document.scene().materials.at(s.blue).baseColorTexture.texture;
        const SamplerId sampler = document.scene().textures.at(texture).sampler;
        QCOMPARE(document.scene().samplers.at(sampler).wrapS, Wrap::ClampToEdge);
        auto* offset = glint::editor::test::fieldNamed<FloatField>(panel, "    Offset U");
        QVERIFY(offset);
        emit offset->edited(0.25);
        QCOMPARE(document.scene().materials.at(s.blue).baseColorTexture.transform.offset.x, 0.25f);
        document.undo();
        document.undo();
        QCOMPARE(document.scene().samplers.at(sampler).wrapS, Wrap::Repeat);
        QCOMPARE(document.scene().materials.at(s.blue).baseColorTexture.transform.offset.x, 0.0f);
    }

    // GLINT_materials_volume_scatter's fields beside the attenuation: one undo step each, named
    // "Change volume", anisotropy typed past its range held to it.
    void scatterFieldsEditTheVolume() {
        Document document;
        Sample s = sample();
        document.newScene(s.scene);
        PropertiesPanel panel(document, false);
        document.setSelection({s.ball});
        QTRY_VERIFY(glint::editor::test::fieldNamed<QWidget>(panel, "Scatter colour") != nullptr);
        auto* anisotropy = glint::editor::test::fieldNamed<QDoubleSpinBox>(panel, "Scatter anisotropy");
        QVERIFY(anisotropy);
        anisotropy->setValue(0.5);
        QCOMPARE(document.scene().materials.at(s.grey).scatterAnisotropy, 0.5f);
        QCOMPARE(document.history().label(document.history().index() - 1), std::string("Change volume"));
        anisotropy->setValue(-3.0);
        QCOMPARE(document.scene().materials.at(s.grey).scatterAnisotropy, -0.99f);
        document.undo();
        document.undo();
        QCOMPARE(document.scene().materials.at(s.grey).scatterAnisotropy, 0.0f);
        QVERIFY(document.scene().materials.at(s.grey) == s.scene.materials.at(s.grey));
    }

    void missingAndBrokenFilesAreNamed() {
        Document document;
        const Sample s = sample();
        document.newScene(s.scene);
        const Scene before = document.scene();
        const std::size_t steps = document.history().index();
        const QString missing = temp_.filePath("nowhere.png");
        QString error = loadTextureFile(document, s.grey, *findTextureSlot("normal"), missing);
        QVERIFY2(error.contains("nowhere.png"), qPrintable(error));
        QFile broken(temp_.filePath("broken.png"));
        QVERIFY(broken.open(QIODevice::WriteOnly));
        broken.write("this is not a PNG at all");
        broken.close();
        error = loadTextureFile(document, s.grey, *findTextureSlot("normal"), broken.fileName());
        QVERIFY2(error.contains("broken.png"), qPrintable(error));
        // An image bomb: a PNG header declaring 65535 x 65535 pixels, refused before it is read.
        const QString bomb = temp_.filePath("bomb.png");
        QVERIFY(QFile::copy(GLINT_TEST_DATA_DIR "/../fuzz/seeds/image_decode/bomb-65535x65535.png", bomb));
        error = loadTextureFile(document, s.grey, *findTextureSlot("baseColor"), bomb);
        QVERIFY2(error.contains("bomb.png") && error.contains("more than the limit of 268435456 pixels"), qPrintable(error));
        QCOMPARE(document.history().index(), steps);
        QVERIFY(document.scene() == before);
    }
};

QTEST_MAIN(TestMaterials)
#include "test_materials.moc"
