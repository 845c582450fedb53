// Pick focus under Xvfb: through a scene camera, Ctrl+Shift+F and a click on a box set the camera's
// focus distance to the box face's depth along the view axis (within 1 %), as one undo step; without
// a scene camera, or through one whose camera path sets the focus, the status bar explains and
// nothing changes. 128x96 px, llvmpipe.
#include "test_viewport_scene.h"

#include "editor/viewport/focus_pick.h"
#include "editor/viewport/render_view.h"
#include "editor/viewport/viewport.h"

#include <QAction>
#include <QMainWindow>
#include <QMouseEvent>
#include <QStatusBar>
#include <QtTest>

using namespace glint;
using namespace glint::editor;

namespace {

void click(QWidget& w, QPointF at) {
    for (const auto type : {QEvent::MouseButtonPress, QEvent::MouseButtonRelease}) {
        QMouseEvent event(type, at, w.mapToGlobal(at), Qt::LeftButton,
                          type == QEvent::MouseButtonPress ? Qt::LeftButton : Qt::NoButton, Qt::NoModifier);
        QCoreApplication::sendEvent(&w, &event);
    }
}

float focusOf(const Document& document, NodeId camera) { return document.scene().at(camera).get<Camera>()->focusDistance; }

} // namespace

class TestViewportFocus : public QObject {
    Q_OBJECT
private slots:
    void init() {
        document_ = std::make_unique<Document>();
        document_->scene().settings.environment.color = glm::vec3(0.8f);
        // A wall 20 x 20 m whose front face is at z = 0.5, seen from a camera at z = 5 looking along -Z.
        test::addShape(*document_, "wall", ShapeKind::Box, {0.0f, 0.0f, 0.0f}, {20.0f, 20.0f, 1.0f});
        Node node;
        node.name = "shot";
        node.local.translation = {0.0f, 0.0f, 5.0f};
        Camera lens;
        lens.focusDistance = 10.0f;
        lens.lensRadius = 0.05f;
        node.component = lens;
        auto add = std::make_unique<AddNode>(std::move(node));
        AddNode* command = add.get();
        document_->push(std::move(add));
        camera_ = command->nodeId();
        document_->history().setClean();
        window_ = std::make_unique<QMainWindow>();
        viewport_ = new Viewport(*document_, window_.get());
        window_->setCentralWidget(viewport_);
        window_->resize(128, 96);
        window_->show();
        QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
    }
    void cleanup() {
        window_.reset();
        document_.reset();
    }

    void withoutASceneCameraItExplains() {
        viewport_->pickFocusAction()->trigger();
        QVERIFY2(window_->statusBar()->currentMessage().contains("scene camera"),
                 qPrintable(window_->statusBar()->currentMessage()));
        QVERIFY(!viewport_->view().focusPickArmed());
        click(viewport_->view(), {64, 48}); // an ordinary click: selects, changes no focus
        QCOMPARE(focusOf(*document_, camera_), 10.0f);
        QVERIFY(!document_->isModified());
    }

    void clickSetsTheDepthAlongTheViewAxis() {
        document_->setSelection({camera_});
        viewport_->lookThroughAction()->trigger();
        QCOMPARE(viewport_->view().lookThrough(), camera_);
        const std::size_t steps = document_->history().index();
        viewport_->pickFocusAction()->trigger();
        QVERIFY(viewport_->view().focusPickArmed());
        // Off-centre: the ray is longer than 4.5 m, the depth along the view axis is not.
        RenderView& view = viewport_->view();
        click(view, {view.width() * 0.85, view.height() * 0.2});
        QVERIFY(!view.focusPickArmed());
        const float focus = focusOf(*document_, camera_);
        QVERIFY2(std::abs(focus - 4.5f) <= 0.01f * 4.5f, qPrintable(QString::number(double(focus))));
        QVERIFY(window_->statusBar()->currentMessage().contains("4.500"));
        QCOMPARE(document_->history().index(), steps + 1); // one undo step
        document_->undo();
        QCOMPARE(focusOf(*document_, camera_), 10.0f);
    }

    void aCameraPathKeepsItsFocus() {
        // The keys of a camera path set its focus over time: pick focus explains and changes nothing.
        Node node;
        node.name = "dolly";
        node.local.translation = {0.0f, 0.0f, 5.0f};
        Camera lens;
        lens.focusDistance = 10.0f;
        for (const double t : {0.0, 1.0}) {
            CameraKey key;
            key.time = t;
            key.position = {0.0, 0.0, 5.0};
            key.focusDistance = 10.0f;
            lens.path.keys.push_back(key);
        }
        node.component = lens;
        auto add = std::make_unique<AddNode>(std::move(node));
        AddNode* command = add.get();
        document_->push(std::move(add));
        const NodeId dolly = command->nodeId();
        const std::size_t steps = document_->history().index();
        document_->setSelection({dolly});
        viewport_->lookThroughAction()->trigger();
        viewport_->pickFocusAction()->trigger();
        click(viewport_->view(), {64, 48});
        QVERIFY2(window_->statusBar()->currentMessage().contains("camera path"), qPrintable(window_->statusBar()->currentMessage()));
        QCOMPARE(focusOf(*document_, dolly), 10.0f);
        QCOMPARE(document_->history().index(), steps);
    }

    void depthIsMeasuredAlongTheAxis() {
        // Pure math: a point 3 m aside at 4 m depth is 4 m away for the focus plane, 5 m along its ray.
        const auto depth = depthAlongView({0, 0, 0}, {0, 0, -1}, {3, 0, -4});
        QVERIFY(depth && std::abs(*depth - 4.0) < 1e-12);
        QVERIFY(!depthAlongView({0, 0, 0}, {0, 0, -1}, {0, 0, 1}));
    }

private:
    std::unique_ptr<Document> document_;
    std::unique_ptr<QMainWindow> window_;
    Viewport* viewport_ = nullptr;
    NodeId camera_;
};

int main(int argc, char** argv) {
    test::prepareGlApplication();
    QApplication app(argc, argv);
    TestViewportFocus test;
    return QTest::qExec(&test, argc, argv);
}
#include "test_viewport_focus.moc"
