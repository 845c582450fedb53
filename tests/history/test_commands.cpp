// Each command's apply/revert restores the scene exactly, and says what it changed.
#include "every_command.h"
#include "sample_scene.h"
#include "scene/history/asset_commands.h"
#include "scene/history/camera_path_commands.h"
#include "scene/history/material_commands.h"
#include "scene/history/node_commands.h"
#include "scene/history/set_node_field.h"
#include "scene/history/settings_commands.h"

#include <QtTest>

using namespace glint;
using namespace glint::test;

namespace {

// Apply, revert, apply: the revert must give back `scene` exactly, the second apply the
// state of the first. Returns the state after the command.
Scene checkUndoable(Scene scene, Command& command) {
    const Scene before = scene;
    command.apply(scene);
    const Scene after = scene;
    command.revert(scene);
    [&] { QVERIFY2(scene == before, qPrintable("revert of " + QString::fromStdString(command.typeName()))); }();
    command.apply(scene);
    [&] { QVERIFY2(scene == after, qPrintable("re-apply of " + QString::fromStdString(command.typeName()))); }();
    return after;
}

bool near(const glm::mat4& a, const glm::mat4& b, float tolerance) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (std::abs(a[c][r] - b[c][r]) > tolerance) return false;
    return true;
}

} // namespace

class TestCommands : public QObject {
    Q_OBJECT
private slots:
    void everyCommandRevertsExactly_data() {
        QTest::addColumn<int>("position");
        SampleIds ids;
        sampleScene(&ids);
        const auto commands = oneOfEachCommand(ids);
        for (std::size_t i = 0; i < commands.size(); ++i)
            QTest::newRow((std::to_string(i) + " " + commands[i]->typeName()).c_str()) << static_cast<int>(i);
    }

    void everyCommandRevertsExactly() {
        QFETCH(int, position);
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        auto commands = oneOfEachCommand(ids);
        for (int i = 0; i < position; ++i) commands[static_cast<std::size_t>(i)]->apply(scene);
        const Scene after = checkUndoable(scene, *commands[static_cast<std::size_t>(position)]);
        QVERIFY(!(after == scene)); // every command in the list really changes something
    }

    void removeNodeRestoresSubtreeIdsAndOrder() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        RemoveNode remove(ids.ball);
        const ChangeSet changes = remove.apply(scene);
        QVERIFY(!scene.contains(ids.ball));
        QVERIFY(!scene.contains(ids.lamp));
        QCOMPARE(scene.at(ids.world).children, (std::vector<NodeId>{ids.floor, ids.triangle}));
        QVERIFY(changes.has(Change::Structure) && changes.has(Change::Geometry) && changes.has(Change::Light));
        QCOMPARE(changes.nodes, (std::set<NodeId>{ids.ball, ids.lamp}));
        remove.revert(scene);
        QCOMPARE(scene.at(ids.world).children, (std::vector<NodeId>{ids.floor, ids.ball, ids.triangle}));
        QVERIFY(scene == sampleScene());
    }

    void removingTheActiveCameraClearsItUntilUndo() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        RemoveNode remove(ids.camera);
        QVERIFY(remove.apply(scene).has(Change::Camera));
        QCOMPARE(scene.settings.activeCamera, NodeId{});
        remove.revert(scene);
        QCOMPARE(scene.settings.activeCamera, ids.camera);
    }

    // A replayed duplicate's recorded copy ids must each name a new node (fuzz_command_log found a
    // log with id 0, which apply turned into a fresh id and revert then could not find).
    void duplicateRefusesRecordedIdsThatNameNoNewNode() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        const Scene start = scene;
        const auto refused = [&](std::vector<NodeId> copies) {
            copies.resize(scene.subtree(ids.ball).size(), NodeId{500});
            try {
                DuplicateNode(ids.ball, copies).apply(scene);
            } catch (const std::invalid_argument&) {
                return scene == start;
            }
            return false;
        };
        QVERIFY(refused({NodeId{}}));               // invalid
        QVERIFY(refused({ids.floor}));              // taken
        QVERIFY(scene.subtree(ids.ball).size() < 2 || refused({NodeId{500}, NodeId{500}})); // repeated
    }

    void duplicateCopiesTheSubtreeWithFreshIdsAfterTheOriginal() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        const NodeId next = scene.peekNextNodeId();
        DuplicateNode duplicate(ids.ball);
        duplicate.apply(scene);
        const std::vector<NodeId> copies{next, NodeId{next.value + 1}};
        QCOMPARE(duplicate.copyIds(), copies);
        QCOMPARE(scene.at(ids.world).children, (std::vector<NodeId>{ids.floor, ids.ball, copies[0], ids.triangle}));
        QCOMPARE(scene.at(copies[0]).children, std::vector<NodeId>{copies[1]});
        QCOMPARE(scene.at(copies[1]).component, scene.at(ids.lamp).component);
        duplicate.revert(scene);
        duplicate.apply(scene); // redo reuses the ids of the first apply
        QCOMPARE(scene.at(ids.world).children[2], copies[0]);
    }

    void reparentKeepsTheWorldTransformWhenAsked() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        const glm::mat4 lampWorld = scene.worldFromNode(ids.lamp);
        ReparentNode keep(ids.lamp, ids.topCamera, 0, true);
        keep.apply(scene);
        QCOMPARE(scene.at(ids.lamp).parent, ids.topCamera);
        QVERIFY(near(scene.worldFromNode(ids.lamp), lampWorld, 1e-5f));
        keep.revert(scene);

        ReparentNode plain(ids.lamp, ids.topCamera, 0, false);
        plain.apply(scene);
        QCOMPARE(scene.at(ids.lamp).local, sampleScene().at(ids.lamp).local);
    }

    void reparentIntoOwnSubtreeThrowsAndChangesNothing() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        ReparentNode cycle(ids.world, ids.lamp);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, cycle.apply(scene));
        QVERIFY(scene == sampleScene());
    }

    void removingAnAssetInUseIsRefused() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, RemoveAsset<Material>(ids.glass).apply(scene));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, RemoveAsset<Material>(ids.textured).apply(scene)); // by a primitive
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, RemoveAsset<Mesh>(ids.triangleMesh).apply(scene));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, RemoveAsset<Texture>(ids.checker).apply(scene));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, RemoveAsset<Image>(ids.checkerImage).apply(scene));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, RemoveAsset<Sampler>(ids.clamped).apply(scene));
        QVERIFY(scene == sampleScene());
    }

    void cameraKeysStaySortedAndDuplicateTimesAreRefused() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        CameraKey key;
        key.time = 1.0; // taken
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, AddCameraKey(ids.camera, key).apply(scene));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, MoveCameraKey(ids.camera, 0, 2.0).apply(scene));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, AddCameraKey(ids.sun, key).apply(scene)); // not a camera
        QVERIFY(scene == sampleScene());

        MoveCameraKey move(ids.camera, 0, 5.0);
        move.apply(scene);
        const auto& keys = scene.at(ids.camera).get<Camera>()->path.keys;
        QCOMPARE(keys.size(), std::size_t{3});
        QCOMPARE(keys[0].time, 1.0);
        QCOMPARE(keys[2].time, 5.0);
        QCOMPARE(keys[2].position, glm::dvec3(0.0, 1.0, 5.0)); // the key that was first
    }

    void editingACameraKeyKeepsItsTime() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        CameraKey key;
        key.time = 99.0;
        key.yfov = 0.4f;
        EditCameraKey(ids.camera, 1, key).apply(scene);
        const CameraKey& edited = scene.at(ids.camera).get<Camera>()->path.keys[1];
        QCOMPARE(edited.time, 1.0);
        QCOMPARE(edited.yfov, 0.4f);
    }

    void changeSetsNameWhatChanged() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        const ChangeSet moved = SetTransform(ids.ball, Transform{}).apply(scene);
        QCOMPARE(moved.flags, static_cast<std::uint32_t>(Change::Transform));
        QCOMPARE(moved.nodes, std::set<NodeId>{ids.ball});

        const ChangeSet light = SetComponent(ids.sun, Light{.type = LightType::Sun, .intensity = 9.0f}).apply(scene);
        QCOMPARE(light.flags, static_cast<std::uint32_t>(Change::Light));

        Material red = scene.materials.at(ids.red);
        red.metallicFactor = 1.0f;
        const ChangeSet material = SetMaterial(ids.red, red).apply(scene);
        QCOMPARE(material.flags, static_cast<std::uint32_t>(Change::Material));
        QCOMPARE(material.materials, std::set<MaterialId>{ids.red});

        const ChangeSet shapeToLight = SetComponent(ids.ball, Light{}).apply(scene);
        QVERIFY(shapeToLight.has(Change::Geometry) && shapeToLight.has(Change::Light) && shapeToLight.has(Change::Structure));
        QCOMPARE(shapeToLight.materials, std::set<MaterialId>{ids.glass});
    }

    void renamesAndDisplaySettingsLeaveTheImageAlone() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        QVERIFY(!affectsImage(RenameNode(ids.ball, "orb").apply(scene)));

        ProjectSettings display = scene.settings;
        display.render.exposure = 2.0f;
        display.render.tonemapper = Tonemapper::PbrNeutral;
        const ChangeSet displayChange = SetProjectSettings(display).apply(scene);
        QCOMPARE(displayChange.flags, static_cast<std::uint32_t>(Change::Display));
        QVERIFY(!affectsImage(displayChange));

        ProjectSettings output = scene.settings;
        output.output.path = "frames/shot_####.exr";
        QVERIFY(!affectsImage(SetProjectSettings(output).apply(scene)));

        QVERIFY(!affectsImage(AddAsset<Material>(Material{}).apply(scene)));
        QVERIFY(affectsImage(SetVisibility(ids.ball, false).apply(scene)));

        ProjectSettings render = scene.settings;
        render.render.bounces = 8;
        const ChangeSet renderChange = SetProjectSettings(render).apply(scene);
        QCOMPARE(renderChange.flags, static_cast<std::uint32_t>(Change::Settings));
        QVERIFY(affectsImage(renderChange));

        ProjectSettings environment = scene.settings;
        environment.environment.intensity = 0.5f;
        QCOMPARE(SetProjectSettings(environment).apply(scene).flags, static_cast<std::uint32_t>(Change::Environment));

        // Fog re-uploads the scene as the environment does, one way and back.
        ProjectSettings fog = scene.settings;
        fog.fog.density = 0.2f;
        SetProjectSettings fogEdit(fog);
        QCOMPARE(fogEdit.apply(scene).flags, static_cast<std::uint32_t>(Change::Environment));
        QCOMPARE(fogEdit.revert(scene).flags, static_cast<std::uint32_t>(Change::Environment));
        QCOMPARE(scene.settings.fog.density, 0.0f);
    }

    void changeSetsMergeFlagsAndIds() {
        ChangeSet changes;
        QVERIFY(changes.empty());
        QVERIFY(!affectsImage(changes));
        changes.merge(nodeChange(Change::Name, NodeId{3}));
        QVERIFY(!changes.empty());
        QVERIFY(!affectsImage(changes));
        ChangeSet material;
        material.add(Change::Material).materials.insert(MaterialId{2});
        changes.merge(material);
        QVERIFY(changes.has(Change::Name) && changes.has(Change::Material) && !changes.has(Change::Geometry));
        QCOMPARE(changes.nodes, std::set<NodeId>{NodeId{3}});
        QCOMPARE(changes.materials, std::set<MaterialId>{MaterialId{2}});
        QVERIFY(affectsImage(changes));
    }

    // A primitive's material: refuses a material or primitive that does not exist (scene untouched),
    // names the mesh and both materials, and a drag over several materials merges into one step.
    void primitiveMaterialIsCheckedAndMerges() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        const Scene start = scene;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, SetPrimitiveMaterial(ids.triangleMesh, 0, MaterialId{999}).apply(scene));
        QVERIFY_THROWS_EXCEPTION(std::out_of_range, SetPrimitiveMaterial(ids.triangleMesh, 7, ids.red).apply(scene));
        QVERIFY(scene == start);
        SetPrimitiveMaterial first(ids.triangleMesh, 0, ids.red);
        const ChangeSet changes = first.apply(scene);
        QVERIFY(changes.has(Change::Geometry));
        QCOMPARE(changes.meshes, std::set<MeshId>{ids.triangleMesh});
        QCOMPARE(changes.materials, (std::set<MaterialId>{ids.red, ids.textured}));
        SetPrimitiveMaterial second(ids.triangleMesh, 0, ids.glass);
        second.apply(scene);
        QVERIFY(first.mergeWith(second));
        QVERIFY(!first.mergeWith(SetPrimitiveMaterial(ids.triangleMesh, 1, ids.glass)));
        first.revert(scene);
        QVERIFY(scene == start);
    }

    void addNodeReusesItsIdOnRedo() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        Node empty;
        empty.name = "empty";
        AddNode add(empty, ids.world, 0);
        const ChangeSet changes = add.apply(scene);
        const NodeId id = add.nodeId();
        QCOMPARE(changes.flags, static_cast<std::uint32_t>(Change::Structure));
        QCOMPARE(scene.at(ids.world).children.front(), id);
        add.revert(scene);
        QVERIFY(!scene.contains(id));
        add.apply(scene);
        QCOMPARE(scene.at(ids.world).children.front(), id);
    }
};

QTEST_APPLESS_MAIN(TestCommands)
#include "test_commands.moc"
