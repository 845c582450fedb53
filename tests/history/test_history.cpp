// History on its own: do/undo/redo, merging within one interaction, macros, the clean state,
// bounds, listeners and jumps (after Godot's tests/core/object/test_undo_redo.h).
#include "sample_scene.h"
#include "scene/history/asset_commands.h"
#include "scene/history/history.h"
#include "scene/history/set_node_field.h"

#include <QtTest>

using namespace glint;
using namespace glint::test;

namespace {

Transform at(float x) {
    Transform t;
    t.translation = {x, 0.0f, 0.0f};
    return t;
}

CommandPtr moveTo(NodeId node, float x, std::uint64_t interaction = 0) {
    auto command = std::make_unique<SetTransform>(node, at(x));
    command->interaction = interaction;
    return command;
}

CommandPtr rename(NodeId node, std::string name, std::uint64_t interaction = 0) {
    auto command = std::make_unique<RenameNode>(node, std::move(name));
    command->interaction = interaction;
    return command;
}

float xOf(const Scene& scene, NodeId node) { return scene.at(node).local.translation.x; }

} // namespace

class TestHistory : public QObject {
    Q_OBJECT
private slots:
    void pushAppliesUndoRevertsRedoReapplies() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        History history(scene);
        QVERIFY(!history.canUndo());
        QVERIFY(!history.canRedo());

        history.push(moveTo(ids.ball, 3.0f));
        QCOMPARE(xOf(scene, ids.ball), 3.0f);
        QCOMPARE(history.index(), std::size_t{1});
        QVERIFY(history.canUndo());

        history.undo();
        QVERIFY(scene == sampleScene());
        QVERIFY(history.canRedo());
        history.redo();
        QCOMPARE(xOf(scene, ids.ball), 3.0f);
        QVERIFY(!history.canRedo());
        QVERIFY(history.undo().has(Change::Transform));
        QVERIFY(history.redo().has(Change::Transform));
    }

    void undoAndRedoAtTheEndsDoNothing() {
        Scene scene = sampleScene();
        History history(scene);
        QVERIFY(history.undo().empty());
        QVERIFY(history.redo().empty());
        QVERIFY(scene == sampleScene());
    }

    void pushAfterUndoDiscardsTheRedoSteps() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        History history(scene);
        history.push(moveTo(ids.ball, 1.0f));
        history.push(moveTo(ids.ball, 2.0f));
        history.undo();
        history.push(rename(ids.ball, "orb"));
        QCOMPARE(history.count(), std::size_t{2});
        QVERIFY(!history.canRedo());
        QCOMPARE(xOf(scene, ids.ball), 1.0f);
    }

    void editsOfOneInteractionMergeIntoOneStep() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        History history(scene);
        const std::uint64_t drag = history.beginInteraction();
        for (int i = 1; i <= 5; ++i) history.push(moveTo(ids.ball, float(i), drag));
        QCOMPARE(history.count(), std::size_t{1});
        QCOMPARE(xOf(scene, ids.ball), 5.0f);
        history.undo();
        QVERIFY(scene == sampleScene());
        history.redo();
        QCOMPARE(xOf(scene, ids.ball), 5.0f);
    }

    void editsOfDifferentInteractionsStaySeparate() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        History history(scene);
        history.push(moveTo(ids.ball, 1.0f, history.beginInteraction()));
        history.push(moveTo(ids.ball, 2.0f, history.beginInteraction()));
        QCOMPARE(history.count(), std::size_t{2});
        history.undo();
        QCOMPARE(xOf(scene, ids.ball), 1.0f);
    }

    void revertingAnInteractionUndoesItsStepsAndLeavesNoRedo() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        History history(scene);
        history.push(moveTo(ids.ball, 1.0f, history.beginInteraction()));
        const Scene afterFirst = scene;
        const std::uint64_t drag = history.beginInteraction();
        history.push(moveTo(ids.ball, 2.0f, drag));
        history.push(rename(ids.ball, "orb", drag)); // another target: a second step of the drag
        history.push(moveTo(ids.ball, 3.0f, drag));
        QCOMPARE(history.count(), std::size_t{4});
        QVERIFY(history.revertInteraction(drag + 1).empty()); // not the top's: nothing happens
        QCOMPARE(history.count(), std::size_t{4});
        const ChangeSet changes = history.revertInteraction(drag);
        QVERIFY(changes.has(Change::Transform));
        QVERIFY(scene == afterFirst);
        QCOMPARE(history.count(), std::size_t{1});
        QVERIFY(!history.canRedo());
        QVERIFY(history.revertInteraction(0).empty());
        history.undo();
        QVERIFY(scene == sampleScene());
    }

    void oneOffEditsNeverMerge() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        History history(scene);
        history.push(moveTo(ids.ball, 1.0f));
        history.push(moveTo(ids.ball, 2.0f));
        QCOMPARE(history.count(), std::size_t{2});
    }

    void oneInteractionOnTwoTargetsDoesNotMerge() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        History history(scene);
        const std::uint64_t drag = history.beginInteraction();
        history.push(moveTo(ids.ball, 1.0f, drag));
        history.push(moveTo(ids.floor, 1.0f, drag));
        history.push(rename(ids.floor, "ground", drag));
        QCOMPARE(history.count(), std::size_t{3});
    }

    void interactionSerialsAreFreshPerHistory() {
        Scene scene = sampleScene();
        History first(scene);
        History second(scene);
        QCOMPARE(first.beginInteraction(), std::uint64_t{1});
        QCOMPARE(first.beginInteraction(), std::uint64_t{2});
        QCOMPARE(second.beginInteraction(), std::uint64_t{1}); // no shared counter
    }

    void macroUndoesAndRedoesAsOneStep() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        History history(scene);
        history.beginMacro("Move and rename");
        history.push(moveTo(ids.ball, 4.0f));
        QCOMPARE(xOf(scene, ids.ball), 4.0f); // applied at once
        history.push(rename(ids.ball, "orb"));
        history.endMacro();
        QCOMPARE(history.count(), std::size_t{1});
        QCOMPARE(history.label(0), std::string("Move and rename"));
        const Scene after = scene;
        history.undo();
        QVERIFY(scene == sampleScene());
        history.redo();
        QVERIFY(scene == after);
    }

    void nestedMacrosJoinTheOuterOne() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        History history(scene);
        history.beginMacro("outer");
        history.push(moveTo(ids.ball, 1.0f));
        history.beginMacro("inner");
        history.push(rename(ids.ball, "orb"));
        history.endMacro();
        QVERIFY(history.inMacro());
        history.endMacro();
        QCOMPARE(history.count(), std::size_t{1});
        QCOMPARE(history.label(0), std::string("outer"));
    }

    void anEmptyMacroLeavesNoStep() {
        Scene scene = sampleScene();
        History history(scene);
        history.beginMacro("nothing");
        history.endMacro();
        QCOMPARE(history.count(), std::size_t{0});
        QVERIFY_THROWS_EXCEPTION(std::logic_error, history.endMacro());
    }

    void undoIsRefusedWhileAMacroIsOpen() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        History history(scene);
        history.push(moveTo(ids.ball, 1.0f));
        history.beginMacro("open");
        QVERIFY(!history.canUndo());
        QVERIFY_THROWS_EXCEPTION(std::logic_error, history.undo());
        QVERIFY_THROWS_EXCEPTION(std::logic_error, history.jumpTo(0));
        history.endMacro();
        QVERIFY(history.canUndo());
    }

    void dragsMergeInsideAMacro() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        History history(scene);
        const std::uint64_t drag = history.beginInteraction();
        history.beginMacro("drag two");
        history.push(moveTo(ids.ball, 1.0f, drag));
        history.push(moveTo(ids.ball, 2.0f, drag));
        history.push(moveTo(ids.floor, 2.0f, drag));
        history.endMacro();
        const nlohmann::json children = history.log().at(0).at("children");
        QCOMPARE(children.size(), std::size_t{2});
        QCOMPARE(children[0].at("value").at("translation")[0].get<float>(), 2.0f);
    }

    // A field dragged with two nodes selected: a macro per drag step. Steps of one interaction merge
    // into one undo step holding the last values and the first old ones; another drag does not merge.
    void macroStepsOfOneDragMerge() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        const Scene start = scene;
        History history(scene);
        const auto step = [&](float x, std::uint64_t drag) {
            history.beginMacro("edit 2 nodes");
            history.push(moveTo(ids.ball, x, drag));
            history.push(moveTo(ids.floor, x, drag));
            history.endMacro();
        };
        const std::uint64_t drag = history.beginInteraction();
        for (float x : {1.0f, 2.0f, 3.0f}) step(x, drag);
        QCOMPARE(history.count(), std::size_t{1});
        QCOMPARE(scene.at(ids.ball).local.translation.x, 3.0f);
        QCOMPARE(scene.at(ids.floor).local.translation.x, 3.0f);
        step(4.0f, history.beginInteraction());
        QCOMPARE(history.count(), std::size_t{2});
        history.undo();
        history.undo();
        QVERIFY(scene == start);
    }

    // A drag that adds an asset on its first step and edits it on the next (auto key on a node
    // without keys: the track is created, then its key moves) is one step: the edits merge into
    // the addition, whose undo removes the asset and whose redo adds the last value.
    void editsOfAnAssetMergeIntoItsAdditionWithinADrag() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        const Scene start = scene;
        History history(scene);
        const std::uint64_t drag = history.beginInteraction();
        auto added = std::make_unique<AddAsset<Material>>(Material{});
        added->interaction = drag;
        auto* addition = added.get();
        history.push(std::move(added));
        const MaterialId id = addition->id();
        for (float roughness : {0.2f, 0.4f}) {
            Material m;
            m.roughnessFactor = roughness;
            auto edit = std::make_unique<SetAsset<Material>>(id, m);
            edit->interaction = drag;
            history.push(std::move(edit));
        }
        QCOMPARE(history.count(), std::size_t{1});
        QCOMPARE(scene.materials.at(id).roughnessFactor, 0.4f);
        history.undo();
        QVERIFY(scene == start);
        history.redo();
        QCOMPARE(scene.materials.at(id).roughnessFactor, 0.4f);
        // Another interaction's edit stays a step of its own.
        auto later = std::make_unique<SetAsset<Material>>(id, Material{});
        later->interaction = history.beginInteraction();
        history.push(std::move(later));
        QCOMPARE(history.count(), std::size_t{2});
    }

    void cleanStateFollowsUndoAndRedo() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        History history(scene);
        QVERIFY(history.isClean());
        history.push(moveTo(ids.ball, 1.0f));
        QVERIFY(!history.isClean());
        history.setClean();
        QVERIFY(history.isClean());
        history.push(moveTo(ids.ball, 2.0f));
        QVERIFY(!history.isClean());
        history.undo();
        QVERIFY(history.isClean());
        history.undo();
        QVERIFY(!history.isClean());
        history.redo();
        QVERIFY(history.isClean());
    }

    void pushingAfterUndoingPastCleanMakesCleanUnreachable() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        History history(scene);
        history.push(moveTo(ids.ball, 1.0f));
        history.push(moveTo(ids.ball, 2.0f));
        history.setClean();
        history.undo();
        history.push(rename(ids.ball, "orb"));
        QCOMPARE(history.cleanIndex(), std::optional<std::size_t>{});
        history.undo();
        QVERIFY(!history.isClean());
        history.undo();
        QVERIFY(!history.isClean());
    }

    void mergingIntoTheCleanStepMakesCleanUnreachable() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        History history(scene);
        const std::uint64_t drag = history.beginInteraction();
        history.push(moveTo(ids.ball, 1.0f, drag));
        history.setClean();
        history.push(moveTo(ids.ball, 2.0f, drag));
        QCOMPARE(history.count(), std::size_t{1});
        QVERIFY(!history.isClean()); // the saved state had x = 1; the scene has x = 2
    }

    void depthBoundDropsTheOldestAndShiftsClean() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        History history(scene, HistoryLimits{.maxDepth = 3});
        history.push(moveTo(ids.ball, 1.0f));
        history.push(moveTo(ids.ball, 2.0f));
        history.setClean(); // index 2
        history.push(moveTo(ids.ball, 3.0f));
        history.push(moveTo(ids.ball, 4.0f)); // drops the first
        QCOMPARE(history.count(), std::size_t{3});
        QCOMPARE(history.index(), std::size_t{3});
        QCOMPARE(history.cleanIndex(), std::optional<std::size_t>{1});
        history.jumpTo(0);
        QCOMPARE(xOf(scene, ids.ball), 1.0f); // the oldest kept step starts after the first move
        history.jumpTo(3);
        history.push(moveTo(ids.ball, 5.0f));
        history.push(moveTo(ids.ball, 6.0f)); // the clean step is gone now
        QCOMPARE(history.cleanIndex(), std::optional<std::size_t>{});
    }

    void memoryBoundDropsTheOldestButKeepsTheNewest() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        // A rename from one 1000-character name to another, as the second and third pushes are.
        Scene probe = scene;
        probe.setName(ids.ball, std::string(1000, 'z'));
        RenameNode step(ids.ball, std::string(1000, 'a'));
        step.apply(probe);
        History history(scene, HistoryLimits{.maxDepth = 100, .maxBytes = 2 * step.memoryBytes() + 100});
        for (char c : std::string("abc")) history.push(rename(ids.ball, std::string(1000, c)));
        QCOMPARE(history.count(), std::size_t{2});
        QVERIFY(history.memoryBytes() <= history.limits().maxBytes);

        History tiny(scene, HistoryLimits{.maxDepth = 100, .maxBytes = 1});
        tiny.push(rename(ids.ball, "d"));
        tiny.push(rename(ids.ball, "e"));
        QCOMPARE(tiny.count(), std::size_t{1});
        tiny.undo();
        QCOMPARE(scene.at(ids.ball).name, std::string("d"));
    }

    void listenersHearChangesAndIndexMoves() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        History history(scene);
        std::vector<ChangeSet> heard;
        std::vector<std::size_t> indices;
        const auto changeListener = history.addChangeListener([&](const ChangeSet& c) { heard.push_back(c); });
        history.addIndexListener([&](std::size_t index) { indices.push_back(index); });

        history.push(moveTo(ids.ball, 1.0f));
        history.push(rename(ids.ball, "orb"));
        history.undo();
        history.redo();
        QCOMPARE(heard.size(), std::size_t{4});
        QCOMPARE(heard[0], nodeChange(Change::Transform, ids.ball));
        QCOMPARE(heard[2], nodeChange(Change::Name, ids.ball));
        QCOMPARE(indices, (std::vector<std::size_t>{1, 2, 1, 2}));

        history.removeListener(changeListener);
        history.undo();
        QCOMPARE(heard.size(), std::size_t{4});
        QCOMPARE(indices.back(), std::size_t{1});
    }

    void jumpToUndoesOrRedoesSeveralStepsAtOnce() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        History history(scene);
        int notifications = 0;
        history.addChangeListener([&](const ChangeSet&) { ++notifications; });
        history.push(moveTo(ids.ball, 1.0f));
        history.push(rename(ids.ball, "orb"));
        history.push(moveTo(ids.floor, 7.0f));
        QCOMPARE(history.labels(), (std::vector<std::string>{"Move", "Rename", "Move"}));
        notifications = 0;
        const ChangeSet changes = history.jumpTo(0);
        QCOMPARE(notifications, 1);
        QVERIFY(changes.has(Change::Transform) && changes.has(Change::Name));
        QCOMPARE(changes.nodes, (std::set<NodeId>{ids.floor, ids.ball}));
        QVERIFY(scene == sampleScene());
        history.jumpTo(2);
        QCOMPARE(scene.at(ids.ball).name, std::string("orb"));
        QCOMPARE(xOf(scene, ids.floor), 0.0f);
        QVERIFY_THROWS_EXCEPTION(std::out_of_range, history.jumpTo(4));
    }

    void aCommandThatThrowsIsNotRecorded() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        History history(scene);
        QVERIFY_THROWS_EXCEPTION(std::out_of_range, history.push(moveTo(NodeId{999}, 1.0f)));
        QCOMPARE(history.count(), std::size_t{0});
        QVERIFY(scene == sampleScene());
    }

    void logHoldsTheAppliedStepsOnly() {
        SampleIds ids;
        Scene scene = sampleScene(&ids);
        History history(scene);
        history.push(moveTo(ids.ball, 1.0f));
        history.push(rename(ids.ball, "orb"));
        history.undo();
        const nlohmann::json log = history.log();
        QCOMPARE(log.size(), std::size_t{1});
        QCOMPARE(log[0].at("type").get<std::string>(), std::string("set_transform"));
    }
};

QTEST_APPLESS_MAIN(TestHistory)
#include "test_history.moc"
