// The outliner and history models over a real document, checked by QAbstractItemModelTester
// through adds, deletes, duplicates, reparenting drops, renames, undo and redo.
#include "editor_fixtures.h"

#include "editor/document/edit_operations.h"
#include "editor/history_view/history_model.h"
#include "editor/outliner/outliner_model.h"
#include "editor/preferences/language.h"
#include "scene/history/node_commands.h"

#include <QAbstractItemModelTester>
#include <QApplication>
#include <QFile>
#include <QFont>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <functional>
#include <QMimeData>

#include <glm/gtc/matrix_access.hpp>

using namespace glint;
using namespace glint::editor;
using namespace glint::editor::test;

class ModelsTest : public QObject {
    Q_OBJECT
private slots:
    void outlinerFollowsTheDocument();
    void renameAndVisibilityAreCommands();
    void dropReparentsKeepingTheWorldTransform();
    void historyModelListsLabelsAndJumps();
    void importMergesAsOneStep();
    void selectionComesBackOnUndo();
    void translationsAreCompleteAndLoad();
    void unnamedNodesShowDerivedNames();
    void duplicatesAreNamedAsInBlender();
};

void ModelsTest::outlinerFollowsTheDocument() {
    Document document;
    OutlinerModel model(document);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QCOMPARE(document.open(cornellBox()), QString());
    QCOMPARE(model.rowCount(), 9); // nine root nodes in the sample
    QCOMPARE(model.index(0, 0).data().toString(), QString("floor"));
    QCOMPARE(model.index(8, 0).data().toString(), QString("camera"));

    document.setSelection({nodeNamed(document, "tall_block")});
    QCOMPARE(duplicateSelection(document), QString());
    QCOMPARE(model.rowCount(), 10);
    QCOMPARE(document.selection().size(), std::size_t{1});
    QVERIFY(document.selection().front() != nodeNamed(document, "tall_block"));
    QCOMPARE(deleteSelection(document), QString());
    QCOMPARE(model.rowCount(), 9);
    QCOMPARE(addNode(document, "ball", defaultShape(ShapeKind::Sphere)), QString());
    QCOMPARE(model.rowCount(), 10);
    document.undo();
    document.undo();
    QCOMPARE(model.rowCount(), 10); // the duplicate is back
    document.redo();
    document.redo();
    QCOMPARE(model.rowCount(), 10);
    QCOMPARE(model.index(9, 0).data().toString(), QString("ball"));
}

void ModelsTest::renameAndVisibilityAreCommands() {
    Document document;
    OutlinerModel model(document);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QCOMPARE(document.open(cornellBox()), QString());
    const QModelIndex floor = model.index(0, OutlinerModel::NameColumn);
    QVERIFY(model.setData(floor, "ground"));
    QCOMPARE(floor.data().toString(), QString("ground"));
    const QModelIndex visible = model.index(0, OutlinerModel::VisibleColumn);
    QCOMPARE(visible.data(Qt::CheckStateRole).toInt(), int(Qt::Checked));
    QVERIFY(model.setData(visible, Qt::Unchecked, Qt::CheckStateRole));
    QCOMPARE(model.index(0, OutlinerModel::VisibleColumn).data(Qt::CheckStateRole).toInt(), int(Qt::Unchecked));
    QCOMPARE(document.history().count(), std::size_t{2});
    document.undo();
    document.undo();
    QCOMPARE(model.index(0, 0).data().toString(), QString("floor"));
    QVERIFY(document.scene().at(nodeNamed(document, "floor")).visible);
    QVERIFY(document.isModified() == false);
}

void ModelsTest::dropReparentsKeepingTheWorldTransform() {
    Document document;
    OutlinerModel model(document);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QCOMPARE(document.open(cornellBox()), QString());
    // A parent that is moved and scaled, so that keeping the local transform would move the child.
    QCOMPARE(addNode(document, "group", Component{}), QString());
    const NodeId group = document.currentNode();
    Transform t;
    t.translation = {1.0f, 2.0f, 3.0f};
    t.scale = {2.0f, 2.0f, 2.0f};
    document.scene().setLocal(group, t); // direct: the test only needs a moved parent
    const NodeId block = nodeNamed(document, "short_block");
    const glm::mat4 before = document.scene().worldFromNode(block);

    std::unique_ptr<QMimeData> data(model.mimeData({model.indexOf(block)}));
    QVERIFY(model.canDropMimeData(data.get(), Qt::MoveAction, -1, 0, model.indexOf(group)));
    model.dropMimeData(data.get(), Qt::MoveAction, -1, 0, model.indexOf(group));
    QCoreApplication::processEvents(); // the drop is applied once the view's handler returned
    QCOMPARE(document.scene().at(block).parent, group);
    QCOMPARE(model.rowCount(model.indexOf(group)), 1);
    const glm::mat4 after = document.scene().worldFromNode(block);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) QVERIFY(std::abs(before[c][r] - after[c][r]) < 1e-5f);
    // A node cannot be dropped into itself.
    std::unique_ptr<QMimeData> self(model.mimeData({model.indexOf(group)}));
    QVERIFY(!model.canDropMimeData(self.get(), Qt::MoveAction, -1, 0, model.indexOf(block)));
    document.undo();
    QVERIFY(!document.scene().at(block).parent);
}

void ModelsTest::historyModelListsLabelsAndJumps() {
    Document document;
    HistoryModel model(document);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QCOMPARE(document.open(cornellBox()), QString());
    QCOMPARE(addNode(document, "a", defaultLight(LightType::Point)), QString());
    QCOMPARE(renameNode(document, document.currentNode(), "b"), QString());
    QCoreApplication::processEvents();
    QCOMPARE(model.rowCount(), 3);
    QCOMPARE(model.index(2).data().toString(), QString("Rename"));
    QCOMPARE(model.currentRow(), 2);
    document.jumpTo(0);
    QCoreApplication::processEvents();
    QCOMPARE(model.currentRow(), 0);
    QVERIFY(model.index(0).data().toString().contains("saved"));
    QVERIFY(!document.scene().findByName("a"));
    document.jumpTo(2);
    QVERIFY(document.scene().findByName("b"));
}

void ModelsTest::importMergesAsOneStep() {
    Document document;
    QCOMPARE(document.open(cornellBox()), QString());
    const std::size_t nodes = document.scene().nodeCount();
    const std::size_t materials = document.scene().materials.size();
    QCOMPARE(document.importFile(cornellBox()), QString());
    QCOMPARE(document.scene().nodeCount(), 2 * nodes);
    QCOMPARE(document.scene().materials.size(), 2 * materials);
    QCOMPARE(document.history().count(), std::size_t{1});
    QCOMPARE(document.selection().size(), nodes); // the imported roots
    // The copies use the copies' materials, not the originals'.
    const Node& copy = document.scene().at(document.selection()[4]); // left_wall_red
    const Mesh& mesh = document.scene().meshes.at(copy.get<MeshInstance>()->mesh);
    QCOMPARE(document.scene().materials.at(mesh.primitives.front().material).name, std::string("red"));
    QVERIFY(mesh.primitives.front().material.value > materials);
    document.undo();
    QCOMPARE(document.scene().nodeCount(), nodes);
    QVERIFY(!document.isModified());
}

void ModelsTest::selectionComesBackOnUndo() {
    Document document;
    QCOMPARE(document.open(cornellBox()), QString());
    const NodeId floor = nodeNamed(document, "floor");
    document.setSelection({floor});
    QCOMPARE(deleteSelection(document), QString());
    QVERIFY(document.selection().empty());
    document.undo();
    QCOMPARE(document.selection(), std::vector<NodeId>{floor});
}

void ModelsTest::translationsAreCompleteAndLoad() {
    for (const char* lang : {"it", "de", "fr", "es"}) {
        QFile ts(QStringLiteral(GLINT_TRANSLATIONS_DIR "/glint_%1.ts").arg(lang));
        QVERIFY(ts.open(QIODevice::ReadOnly));
        const QByteArray text = ts.readAll();
        QVERIFY2(!text.contains("type=\"unfinished\""), lang);
        QVERIFY(text.count("<translation") > 250);
        Translations translations;
        auto* app = QCoreApplication::instance();
        QCOMPARE(translations.install(*app, lang), QString(lang));
        // A string of the main window, one of a panel and one from the scene core's labels.
        QVERIFY(QCoreApplication::translate("glint::editor::MainWindow", "&Save") != "&Save");
        QVERIFY(QCoreApplication::translate("glint::editor::PropertyForm", "Roughness") != "Roughness");
        QVERIFY(QCoreApplication::translate("glint::editor::CommandLabels", "Rename") != "Rename");
        translations.install(*app, "en");
    }
    QCOMPARE(QCoreApplication::translate("glint::editor::MainWindow", "&Save"), QString("&Save"));
}

// 2CylinderEngine names none of its 82 nodes (issue 17, item 5): rows show the mesh's name, else
// "Node N" / "Camera N", in italics; the filter finds them; nothing is written into the file.
void ModelsTest::unnamedNodesShowDerivedNames() {
    Document document;
    OutlinerModel model(document);
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QCOMPARE(document.open(QStringLiteral(GLINT_TEST_DATA_DIR "/gltf/2CylinderEngine/2CylinderEngine.glb")), QString());
    QCOMPARE(document.scene().nodeCount(), std::size_t{82});
    int rows = 0, derived = 0, meshNamed = 0;
    std::function<void(const QModelIndex&)> walk = [&](const QModelIndex& parent) {
        for (int row = 0; row < model.rowCount(parent); ++row) {
            const QModelIndex index = model.index(row, 0, parent);
            const NodeId id = model.nodeAt(index);
            const Node& node = document.scene().at(id);
            const QString shown = index.data().toString();
            ++rows;
            QVERIFY2(!shown.isEmpty(), "a blank outliner row");
            QVERIFY(node.name.empty());
            derived += index.data(Qt::FontRole).value<QFont>().italic() ? 1 : 0;
            if (const auto* instance = node.get<MeshInstance>()) {
                QCOMPARE(shown, QString::fromStdString(document.scene().meshes.find(instance->mesh)->name));
                ++meshNamed;
            } else if (node.get<Camera>()) {
                QCOMPARE(shown, QString("Camera %1").arg(id.value));
            } else {
                QCOMPARE(shown, QString("Node %1").arg(id.value));
            }
            walk(index);
        }
    };
    walk({});
    QCOMPARE(rows, 82);
    QCOMPARE(derived, 82);
    QVERIFY(meshNamed > 20);
    // Renaming one for real: its own name, upright; confirming the derived one writes nothing.
    const QModelIndex first = model.index(0, 0);
    QVERIFY(model.setData(first, first.data().toString(), Qt::EditRole));
    QCOMPARE(document.history().count(), std::size_t{0});
    QVERIFY(model.setData(first, "engine", Qt::EditRole));
    QCOMPARE(first.data().toString(), QString("engine"));
    QVERIFY(!first.data(Qt::FontRole).value<QFont>().italic());
    document.undo();
    // Saved, the file names no node.
    QTemporaryDir dir;
    QCOMPARE(document.saveAs(dir.filePath("engine.gltf")), QString());
    QFile saved(dir.filePath("engine.gltf"));
    QVERIFY(saved.open(QIODevice::ReadOnly));
    const QJsonArray nodes = QJsonDocument::fromJson(saved.readAll()).object()["nodes"].toArray();
    QCOMPARE(nodes.size(), 82);
    for (const QJsonValue& node : nodes) QVERIFY(!node.toObject().contains("name"));
}

// "Sphere" duplicated is "Sphere.001", as in Blender (it was a second "Sphere"), as one undo step.
void ModelsTest::duplicatesAreNamedAsInBlender() {
    Document document;
    QCOMPARE(addNode(document, "Sphere", defaultShape(ShapeKind::Sphere)), QString());
    const NodeId sphere = nodeNamed(document, "Sphere");
    const auto duplicate = [&](NodeId id) {
        document.setSelection({id});
        const std::size_t steps = document.history().index();
        const QString error = duplicateSelection(document);
        if (!error.isEmpty() || document.history().index() != steps + 1) return std::string("(failed)");
        return document.scene().at(document.currentNode()).name;
    };
    QCOMPARE(duplicate(sphere), std::string("Sphere.001"));
    QCOMPARE(duplicate(sphere), std::string("Sphere.002"));
    QCOMPARE(duplicate(nodeNamed(document, "Sphere.001")), std::string("Sphere.003"));
    document.undo(); // the copy and its name go together
    QVERIFY(!nodeNamed(document, "Sphere.003").valid());
    QCOMPARE(duplicate(nodeNamed(document, "Sphere.002")), std::string("Sphere.003"));
    // A node without a name stays without one (its derived name is shown).
    Node unnamed;
    auto add = std::make_unique<AddNode>(std::move(unnamed));
    AddNode* raw = add.get();
    document.push(std::move(add));
    QCOMPARE(duplicate(raw->nodeId()), std::string());
}

QTEST_MAIN(ModelsTest)
#include "models_test.moc"
