// The timeline: add camera keys from the view at several times, scrub on the ruler, and the
// camera (posed scene and the viewport looking through it) matches the sampled path; key drags,
// deletes and value edits are single undo steps; playback steps whole frames at the project fps
// and loops. Widgets only (no GL): the viewport is never shown.
#include "editor_fixtures.h"
#include "test_viewport_scene.h"

#include "editor/document/keyed_transform.h"
#include "editor/properties/property_edits.h"
#include "editor/timeline/node_key_tracks.h"
#include "editor/viewport/gizmo_drag.h"
#include "editor/timeline/time_ruler.h"
#include "editor/timeline/timeline_panel.h"
#include "editor/viewport/render_view.h"
#include "editor/viewport/viewport.h"
#include "scene/anim/camera_path_sampling.h"
#include "scene/anim/node_keys.h"
#include "scene/history/asset_commands.h"
#include "scene/history/set_node_field.h"
#include "scene/anim/scene_at_time.h"

#include <QAction>
#include <QComboBox>
#include <QImage>
#include <QProcess>
#include <QTemporaryDir>
#include <QDoubleSpinBox>
#include <QMouseEvent>
#include <QtTest>

using namespace glint;
using namespace glint::editor;

namespace {

const CameraPath& pathOf(const Document& d, NodeId camera) { return d.scene().at(camera).get<Camera>()->path; }

void sendMouse(QWidget& w, QEvent::Type type, QPointF at, Qt::MouseButton button, Qt::MouseButtons buttons) {
    QMouseEvent event(type, at, w.mapToGlobal(at), button, buttons, Qt::NoModifier);
    QCoreApplication::sendEvent(&w, &event);
}

} // namespace

class TestTimelineKeys : public QObject {
    Q_OBJECT
private slots:
    void init() {
        document_ = std::make_unique<Document>();
        shapes_ = glint::test::buildShapesScene(*document_);
        viewport_ = std::make_unique<Viewport>(*document_);
        timeline_ = std::make_unique<TimelinePanel>(*document_);
        timeline_->resize(600, 120);
        timeline_->setKeySource([this](double t) { return keyFromView(viewport_->view().camera(), t); });
        timeline_->setCameraMaker([this] { return viewport_->makeSceneCamera(); });
        timeline_->show();
        QVERIFY(QTest::qWaitForWindowExposed(timeline_.get()));
    }
    void cleanup() {
        timeline_.reset();
        viewport_.reset();
        document_.reset();
    }

    // Three keys from three views at t = 0, 1, 2.
    NodeId addThreeKeys() {
        const double yaws[3] = {0.0, 0.8, 1.6};
        for (int i = 0; i < 3; ++i) {
            ViewCamera c = viewport_->view().camera();
            c.yaw = yaws[i];
            c.target = {0.5 * i, 0.0, 0.0};
            viewport_->view().setCamera(c);
            document_->setCurrentTime(double(i));
            timeline_->addKeyAction()->trigger();
        }
        return timeline_->camera();
    }

    void addKeysScrubAndTheCameraFollowsThePath() {
        const NodeId camera = addThreeKeys();
        QVERIFY(camera.valid());
        const CameraPath& path = pathOf(*document_, camera);
        QCOMPARE(path.keys.size(), std::size_t(3));
        // Key 1 holds the view it was taken from.
        ViewCamera v = viewport_->view().camera();
        v.yaw = 0.8;
        v.target = {0.5, 0.0, 0.0};
        QVERIFY(glm::length(path.keys[1].position - v.position()) < 1e-12);

        viewport_->view().setLookThrough(camera);
        // Scrub: a click on the ruler at t = 1.5 s (snapped to the 24 fps frame grid).
        TimeRuler& ruler = timeline_->ruler();
        const QPointF at(ruler.xAt(1.5), ruler.height() / 2.0);
        sendMouse(ruler, QEvent::MouseButtonPress, at, Qt::LeftButton, Qt::LeftButton);
        sendMouse(ruler, QEvent::MouseButtonRelease, at, Qt::LeftButton, Qt::NoButton);
        const double t = document_->currentTime();
        QVERIFY(std::abs(t - 1.5) < 1.0 / 24.0 + 1e-9);
        QCOMPARE(std::round(t * 24.0), t * 24.0); // on a frame

        const CameraKey expected = sampleCameraPath(path, t);
        const Scene posed = sceneAt(document_->scene(), t);
        const glm::dvec3 posedPosition(glm::dvec3(glm::dmat4(posed.worldFromNode(camera))[3]));
        QVERIFY2(glm::length(posedPosition - expected.position) < 1e-5, "posed camera off the path");
        // The viewport looking through the path camera sits on the path and looks along it.
        const ViewCamera& through = viewport_->view().camera();
        QVERIFY(glm::length(through.position() - expected.position) < 1e-4);
        QVERIFY(glm::length(through.forward() - expected.orientation * glm::dvec3(0, 0, -1)) < 1e-4);
        QVERIFY(!(expected.position == path.keys[1].position)); // really between keys
    }

    void dragDeleteAndEditKeysAreSingleUndoSteps() {
        const NodeId camera = addThreeKeys();
        TimeRuler& ruler = timeline_->ruler();
        const std::size_t steps = document_->history().count();
        // Drag key 1 from t = 1 to t = 1.5 in several moves: one step.
        const double y = ruler.height() - 14.0;
        sendMouse(ruler, QEvent::MouseButtonPress, {ruler.xAt(1.0), y}, Qt::LeftButton, Qt::LeftButton);
        for (double t : {1.1, 1.25, 1.4, 1.5}) sendMouse(ruler, QEvent::MouseMove, {ruler.xAt(t), y}, Qt::NoButton, Qt::LeftButton);
        sendMouse(ruler, QEvent::MouseButtonRelease, {ruler.xAt(1.5), y}, Qt::LeftButton, Qt::NoButton);
        QCOMPARE(document_->history().count(), steps + 1);
        QVERIFY(std::abs(pathOf(*document_, camera).keys[1].time - 1.5) < 1.0 / 24.0 + 1e-9);
        document_->undo();
        QCOMPARE(pathOf(*document_, camera).keys[1].time, 1.0);

        // Edit the selected key's fov in the key editor: one step, exact undo.
        ruler.setSelectedKey(1);
        const CameraKey before = pathOf(*document_, camera).keys[1];
        auto fields = timeline_->findChildren<QDoubleSpinBox*>();
        QCOMPARE(fields.size(), 7);
        fields[3]->setValue(60.0);
        QVERIFY(std::abs(pathOf(*document_, camera).keys[1].yfov - float(60.0 * 3.14159265358979 / 180.0)) < 1e-6f);
        document_->undo();
        QCOMPARE(pathOf(*document_, camera).keys[1], before);

        // Delete the selected key; undo brings it back.
        ruler.setSelectedKey(1);
        timeline_->deleteKeyAction()->trigger();
        QCOMPARE(pathOf(*document_, camera).keys.size(), std::size_t(2));
        document_->undo();
        QCOMPARE(pathOf(*document_, camera).keys[1], before);
    }

    // The sphere keyed at x = -1.2 (t = 0) and x = 0.8 (t = 1) with the Key action.
    // Keys at 0 (x = -1.2, where the sphere stands) and at 1 (x = 0.8): K keys the pose shown at
    // each time, and moving the keyed sphere at t = 1 re-keys it there, as an animator works.
    NodeId keySphereTwice() {
        const NodeId sphere = shapes_.sphere;
        document_->setSelection({sphere});
        document_->setCurrentTime(0.0);
        timeline_->keyNodeAction()->trigger();
        document_->setCurrentTime(1.0);
        timeline_->keyNodeAction()->trigger();
        Transform moved = shownTransform(*document_, sphere);
        moved.translation.x = 0.8f;
        if (!pushTransform(*document_, sphere, moved, 0).isEmpty()) return {};
        return sphere;
    }

    static float posedX(const Document& d, NodeId node, double t) { return sceneAt(d.scene(), t).at(node).local.translation.x; }

    // Keys of any node: key twice, the pose between is interpolated (linear, then step); a drag on
    // the node's row moves a key (one undo step); delete and paste; each edit undoes exactly.
    void nodeKeysAreKeyedInterpolatedMovedAndDeleted() {
        const NodeId sphere = keySphereTwice();
        const auto id = nodeKeyAnimation(document_->scene(), sphere);
        QVERIFY(id);
        QCOMPARE(nodeKeyTimes(document_->scene().animations.at(*id), sphere), (std::vector<double>{0.0, 1.0}));
        QVERIFY(std::abs(posedX(*document_, sphere, 0.5) - (-0.2f)) < 1e-5f);
        NodeKeyTracks& tracks = timeline_->nodeTracks();
        QCOMPARE(tracks.rows(), std::vector<NodeId>{sphere});

        // Step: the pose holds the first key until the second.
        QComboBox* interpolation = timeline_->interpolationBox();
        QVERIFY(interpolation->isEnabled());
        QCOMPARE(interpolation->currentData().toInt(), int(Interpolation::Linear));
        interpolation->setCurrentIndex(interpolation->findData(int(Interpolation::Step)));
        emit interpolation->activated(interpolation->currentIndex());
        QVERIFY(std::abs(posedX(*document_, sphere, 0.5) - (-1.2f)) < 1e-5f);
        document_->undo();
        QVERIFY(std::abs(posedX(*document_, sphere, 0.5) - (-0.2f)) < 1e-5f);

        // Drag the key at t = 1 to t = 2 on the sphere's row in several moves: one undo step.
        tracks.resize(timeline_->ruler().width(), tracks.height());
        const std::size_t steps = document_->history().index();
        const double y = tracks.rowCentreY(0);
        sendMouse(tracks, QEvent::MouseButtonPress, {timeline_->ruler().xAt(1.0), y}, Qt::LeftButton, Qt::LeftButton);
        QVERIFY(tracks.selectedKey());
        for (double t : {1.25, 1.5, 2.0}) sendMouse(tracks, QEvent::MouseMove, {timeline_->ruler().xAt(t), y}, Qt::NoButton, Qt::LeftButton);
        sendMouse(tracks, QEvent::MouseButtonRelease, {timeline_->ruler().xAt(2.0), y}, Qt::LeftButton, Qt::NoButton);
        QCOMPARE(document_->history().index(), steps + 1);
        const auto times = nodeKeyTimes(document_->scene().animations.at(*id), sphere);
        QCOMPARE(times.size(), std::size_t(2));
        QVERIFY(std::abs(times[1] - 2.0) < 1.0 / 24.0 + 1e-9);
        QVERIFY(std::abs(posedX(*document_, sphere, 0.5 * times[1]) - (-0.2f)) < 1e-5f);
        document_->undo();
        QCOMPARE(nodeKeyTimes(document_->scene().animations.at(*id), sphere), (std::vector<double>{0.0, 1.0}));

        // Copy the key at 0 and paste it at 3: the sphere is back at -1.2 there.
        tracks.setSelectedKey(NodeKey{sphere, 0.0});
        timeline_->copyNodeKeyAction()->trigger();
        document_->setCurrentTime(3.0);
        timeline_->pasteNodeKeyAction()->trigger();
        QCOMPARE(nodeKeyTimes(document_->scene().animations.at(*id), sphere), (std::vector<double>{0.0, 1.0, 3.0}));
        QVERIFY(std::abs(posedX(*document_, sphere, 3.0) - (-1.2f)) < 1e-5f);
        document_->undo();

        // Delete the selected key, then the last one: the animation goes with it; undo restores.
        tracks.setSelectedKey(NodeKey{sphere, 1.0});
        timeline_->deleteKeyAction()->trigger();
        QCOMPARE(nodeKeyTimes(document_->scene().animations.at(*id), sphere), std::vector<double>{0.0});
        tracks.setSelectedKey(NodeKey{sphere, 0.0});
        timeline_->deleteKeyAction()->trigger();
        QVERIFY(!nodeKeyAnimation(document_->scene(), sphere));
        document_->undo();
        document_->undo();
        QCOMPARE(nodeKeyTimes(document_->scene().animations.at(*id), sphere), (std::vector<double>{0.0, 1.0}));
    }

    // A keyed node shows its keys' pose, so a gizmo drag or a panel edit starts from that pose and
    // keys it at the current time (it would not show otherwise): one undo step per drag, the other
    // keys intact. Off, an unkeyed node's edit stays a plain transform change; Auto key keys it too.
    void editsKeyKeyedNodesAndAutoKeyKeysEveryNode() {
        const NodeId sphere = keySphereTwice();
        const auto id = nodeKeyAnimation(document_->scene(), sphere);
        QVERIFY(id);
        document_->setCurrentTime(0.5);
        QVERIFY(std::abs(shownTransform(*document_, sphere).translation.x - (-0.2f)) < 1e-5f);
        // The gizmo stands where the sphere is shown, and a drag along X from there by 0.5 m...
        const GizmoFrame frame = viewport_->view().gizmoFrame(sphere);
        QVERIFY(std::abs(frame.origin.x - (-0.2)) < 1e-5);
        const glm::vec3 handle = glm::vec3(frame.origin) + glm::vec3(0.5f * float(frame.size), 0.0f, 0.0f);
        const auto rayAt = [](glm::vec3 p) { return bvh::Ray{p + glm::vec3(0.0f, 0.0f, 5.0f), {0.0f, 0.0f, -1.0f}}; };
        const std::size_t steps = document_->history().index();
        GizmoDrag drag(*document_, sphere, frame, GizmoMode::Translate, rayAt(handle));
        QVERIFY(drag.active());
        for (const float dx : {0.1f, 0.3f, 0.5f}) drag.moveTo(rayAt(handle + glm::vec3(dx, 0.0f, 0.0f)), {});
        // ...keys it at 0.5 in one undo step, shown at 0.3; the keys at 0 and 1 stay.
        QCOMPARE(document_->history().index(), steps + 1);
        QCOMPARE(nodeKeyTimes(document_->scene().animations.at(*id), sphere), (std::vector<double>{0.0, 0.5, 1.0}));
        QVERIFY(std::abs(posedX(*document_, sphere, 0.5) - 0.3f) < 1e-4f);
        QVERIFY(std::abs(posedX(*document_, sphere, 1.0) - 0.8f) < 1e-5f);
        document_->undo();
        QCOMPARE(nodeKeyTimes(document_->scene().animations.at(*id), sphere), (std::vector<double>{0.0, 1.0}));
        QVERIFY(std::abs(posedX(*document_, sphere, 0.5) - (-0.2f)) < 1e-5f);
        // The same drag cancelled (Esc) leaves neither a key nor a step to redo; the step before it
        // stays redoable until then.
        const Scene beforeCancel = document_->scene();
        QVERIFY(document_->canRedo());
        GizmoDrag cancelled(*document_, sphere, frame, GizmoMode::Translate, rayAt(handle));
        for (const float dx : {0.2f, 0.4f}) cancelled.moveTo(rayAt(handle + glm::vec3(dx, 0.0f, 0.0f)), {});
        QCOMPARE(nodeKeyTimes(document_->scene().animations.at(*id), sphere).size(), std::size_t(3));
        cancelled.cancel();
        QVERIFY(document_->scene() == beforeCancel);
        QCOMPARE(document_->history().index(), steps);
        QVERIFY(!document_->canRedo());
        cancelled.cancel(); // twice: nothing more happens
        QCOMPARE(document_->history().index(), steps);

        // The panel's field edits the pose shown too: x typed at 0.5 becomes a key there.
        QCOMPARE(editTransform(*document_, sphere, [](Transform& t) { t.translation.x = -1.0f; }, 0), QString());
        QVERIFY(std::abs(posedX(*document_, sphere, 0.5) - (-1.0f)) < 1e-5f);
        QCOMPARE(nodeKeyTimes(document_->scene().animations.at(*id), sphere).size(), std::size_t(3));

        // An unkeyed node, auto key off: a plain edit, no track.
        const NodeId box = shapes_.box;
        const float y = document_->scene().at(box).local.translation.y;
        QCOMPARE(editTransform(*document_, box, [](Transform& t) { t.translation.y += 1.0f; }, 0), QString());
        QVERIFY(!nodeKeyAnimation(document_->scene(), box));
        QCOMPARE(document_->scene().at(box).local.translation.y, y + 1.0f);
        // Auto key on (the timeline's toggle): the edit keys the box at 0.5, undone in one step.
        timeline_->autoKeyAction()->trigger();
        QVERIFY(document_->autoKey());
        const std::size_t before = document_->history().index();
        QCOMPARE(editTransform(*document_, box, [](Transform& t) { t.translation.y += 1.0f; }, 0), QString());
        QCOMPARE(document_->history().index(), before + 1);
        const auto boxKeys = nodeKeyAnimation(document_->scene(), box);
        QVERIFY(boxKeys);
        QCOMPARE(nodeKeyTimes(document_->scene().animations.at(*boxKeys), box), std::vector<double>{0.5});
        QCOMPARE(sceneAt(document_->scene(), 3.0).at(box).local.translation.y, y + 2.0f);
        document_->undo();
        QVERIFY(!nodeKeyAnimation(document_->scene(), box));
        QCOMPARE(document_->scene().at(box).local.translation.y, y + 1.0f);
        // A gizmo drag of the unkeyed box with auto key: its new track and key are one undo step.
        const GizmoFrame boxFrame = viewport_->view().gizmoFrame(box);
        const glm::vec3 boxHandle = glm::vec3(boxFrame.origin) + glm::vec3(0.5f * float(boxFrame.size), 0.0f, 0.0f);
        const std::size_t beforeDrag = document_->history().index();
        GizmoDrag boxDrag(*document_, box, boxFrame, GizmoMode::Translate, rayAt(boxHandle));
        QVERIFY(boxDrag.active());
        for (const float dx : {0.1f, 0.2f, 0.4f}) boxDrag.moveTo(rayAt(boxHandle + glm::vec3(dx, 0.0f, 0.0f)), {});
        QCOMPARE(document_->history().index(), beforeDrag + 1);
        QVERIFY(nodeKeyAnimation(document_->scene(), box));
        document_->undo();
        QVERIFY(!nodeKeyAnimation(document_->scene(), box));
        timeline_->autoKeyAction()->trigger();
        QVERIFY(!document_->autoKey());
    }

    // Keyed in the editor, saved, rendered by `glint render --time 0.5`: the same pixels as the
    // scene with the sphere placed half way (x = -0.2) and no animation; and save -> reopen keeps
    // the keys exactly.
    void nodeKeysRenderBetweenKeysInTheCli() {
        // A fixed camera: without one the CLI frames the scene's bounds, which differ between the files.
        Node camera;
        camera.name = "camera";
        camera.component = Camera{};
        camera.local.translation = {0.0f, 0.5f, 6.0f};
        document_->push(std::make_unique<AddNode>(camera, NodeId{}));
        const NodeId sphere = keySphereTwice();
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString animated = dir.filePath("animated.gltf");
        QCOMPARE(document_->saveAs(animated), QString());
        const Scene saved = document_->scene();

        QCOMPARE(document_->open(animated), QString());
        const NodeId reopened = editor::test::nodeNamed(*document_, "sphere");
        const auto id = nodeKeyAnimation(document_->scene(), reopened);
        QVERIFY(id);
        QCOMPARE(nodeKeyTimes(document_->scene().animations.at(*id), reopened), (std::vector<double>{0.0, 1.0}));
        QVERIFY(std::abs(posedX(*document_, reopened, 0.5) - (-0.2f)) < 1e-5f);

        // The still reference: no animation, the sphere at -0.2.
        document_->push(std::make_unique<RemoveAsset<Animation>>(*id));
        Transform half = document_->scene().at(reopened).local;
        half.translation.x = -0.2f;
        document_->push(std::make_unique<SetTransform>(reopened, half));
        const QString still = dir.filePath("still.gltf");
        QCOMPARE(document_->saveAs(still), QString());
        QVERIFY(saved.at(sphere).local.translation.x == 0.8f); // the rest pose is not the half-way one

        auto render = [&](const QString& scene, const QString& time, const QString& out) {
            QProcess cli;
            cli.start(GLINT_EXECUTABLE, {"render", scene, "--time", time, "--size", "48x32", "--spp", "4", "--out", out});
            QVERIFY(cli.waitForFinished(120000));
            QVERIFY2(cli.exitStatus() == QProcess::NormalExit && cli.exitCode() == 0, cli.readAllStandardError().constData());
        };
        render(animated, "0.5", dir.filePath("animated.png"));
        render(still, "0", dir.filePath("still.png"));
        render(animated, "0", dir.filePath("start.png"));
        const QImage a(dir.filePath("animated.png")), b(dir.filePath("still.png")), c(dir.filePath("start.png"));
        QVERIFY(!a.isNull() && !b.isNull());
        QCOMPARE(a, b);
        QVERIFY(a != c); // the sphere really moved
    }

    void constantSpeedToggleIsACommand() {
        const NodeId camera = addThreeKeys();
        timeline_->constantSpeedAction()->trigger();
        QVERIFY(pathOf(*document_, camera).constantSpeed);
        document_->undo();
        QVERIFY(!pathOf(*document_, camera).constantSpeed);
    }

    void playbackStepsFramesAndLoops() {
        addThreeKeys();
        document_->setCurrentTime(0.0);
        for (int i = 0; i < 12; ++i) timeline_->stepFrame();
        QCOMPARE(document_->currentTime(), 12.0 / 24.0);
        const double end = timeline_->ruler().range().end; // last key + 1 s
        document_->setCurrentTime(end);
        timeline_->stepFrame();
        QCOMPARE(document_->currentTime(), 0.0); // looped
        timeline_->loopAction()->setChecked(false);
        document_->setCurrentTime(end);
        timeline_->setPlaying(true);
        timeline_->stepFrame();
        QVERIFY(!timeline_->playing());
        QCOMPARE(document_->currentTime(), end);
        // Real playback advances the time.
        document_->setCurrentTime(0.0);
        timeline_->setPlaying(true);
        QTRY_VERIFY_WITH_TIMEOUT(document_->currentTime() >= 3.0 / 24.0, 5000);
        timeline_->setPlaying(false);
    }

private:
    std::unique_ptr<Document> document_;
    std::unique_ptr<Viewport> viewport_;
    std::unique_ptr<TimelinePanel> timeline_;
    glint::test::ShapesScene shapes_;
};

QTEST_MAIN(TestTimelineKeys)
#include "test_timeline_keys.moc"
