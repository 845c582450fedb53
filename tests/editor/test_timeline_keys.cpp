// The timeline: add camera keys from the view at several times, scrub on the ruler, and the
// camera (posed scene and the viewport looking through it) matches the sampled path; key drags,
// deletes and value edits are single undo steps; playback steps whole frames at the project fps
// and loops. Widgets only (no GL): the viewport is never shown.
#include "test_viewport_scene.h"

#include "editor/timeline/time_ruler.h"
#include "editor/timeline/timeline_panel.h"
#include "editor/viewport/render_view.h"
#include "editor/viewport/viewport.h"
#include "scene/anim/camera_path_sampling.h"
#include "scene/anim/scene_at_time.h"

#include <QAction>
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
        test::buildShapesScene(*document_);
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
};

QTEST_MAIN(TestTimelineKeys)
#include "test_timeline_keys.moc"
