// The viewport's render region and BVH heat map in a real window under Xvfb (128x96 px,
// llvmpipe). Region: drawn with a drag after the Ctrl+B action, it is view state (the document
// stays clean); while it is set, pixels outside it are identical from frame to frame (the last
// image stays) while inside the samples add up and the picture changes, also while the view
// moves (real-time configuration); it follows a resize proportionally, the outside scaled;
// clearing (Ctrl+Alt+B) renders the whole view again. Heat map: black (cost 0) where the camera
// rays miss the scene's bounds, coloured over a mesh, with a legend.
#include "test_viewport_scene.h"

#include "editor/viewport/render_view.h"
#include "editor/viewport/viewport.h"

#include <QAction>
#include <QElapsedTimer>
#include <QMainWindow>
#include <QMouseEvent>
#include <QScopeGuard>
#include <QtTest>

#include <algorithm>
#include <vector>

using namespace glint;
using namespace glint::editor;

namespace {

constexpr int kMaxWaitMs = 20000;
constexpr int kBorder = 3; // pixels either side of the region's edge: the dashed frame is drawn there

template <class F> bool waitFor(F done, int ms = kMaxWaitMs) {
    QElapsedTimer t;
    t.start();
    while (!done() && t.elapsed() < ms) QTest::qWait(5);
    return done();
}

void sendMouse(QWidget& w, QEvent::Type type, QPointF at, Qt::MouseButton button, Qt::MouseButtons buttons) {
    QMouseEvent event(type, at, w.mapToGlobal(at), button, buttons, Qt::NoModifier);
    QCoreApplication::sendEvent(&w, &event);
}

// Pixels (in image coordinates) that differ between a and b, inside or outside `region` (widget
// coordinates scaled to the image), skipping a band of `border` pixels around its edge.
struct Differences {
    int inside = 0, outside = 0, insideCount = 0, outsideCount = 0;
};

Differences compare(const QImage& a, const QImage& b, QRectF region, QSize widget, int border = kBorder) {
    Differences d;
    const double sx = double(a.width()) / widget.width(), sy = double(a.height()) / widget.height();
    const QRectF r(region.x() * sx, region.y() * sy, region.width() * sx, region.height() * sy);
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const QPointF p(x + 0.5, y + 0.5);
            const bool in = r.adjusted(border, border, -border, -border).contains(p);
            const bool out = !r.adjusted(-border, -border, border, border).contains(p);
            const bool differs = a.pixel(x, y) != b.pixel(x, y);
            if (in) d.inside += differs, ++d.insideCount;
            if (out) d.outside += differs, ++d.outsideCount;
        }
    return d;
}

} // namespace

class TestViewportRegion : public QObject {
    Q_OBJECT
private slots:
    void init() {
        document_ = std::make_unique<Document>();
        test::buildShapesScene(*document_);
        document_->scene().settings.render.spp = 100000; // never converged here: every paint adds samples
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

    void regionKeepsTheOutsideAndConvergesInside() {
        RenderView& view = viewport_->view();
        QCOMPARE(viewport_->renderRegionAction()->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_B));
        QCOMPARE(viewport_->clearRenderRegionAction()->shortcut(), QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_B));
        QVERIFY(waitFor([&] { return view.stats().samples >= 2; }));
        // Ctrl+B, then a drag over the middle half of the view.
        viewport_->renderRegionAction()->trigger();
        const QPointF from(view.width() * 0.25, view.height() * 0.25), to(view.width() * 0.75, view.height() * 0.75);
        sendMouse(view, QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
        sendMouse(view, QEvent::MouseMove, (from + to) / 2, Qt::NoButton, Qt::LeftButton);
        sendMouse(view, QEvent::MouseButtonRelease, to, Qt::LeftButton, Qt::NoButton);
        QVERIFY(view.renderRegion().has_value());
        QVERIFY(std::abs(view.renderRegion()->x() - 0.25) < 0.02 && std::abs(view.renderRegion()->width() - 0.5) < 0.02);
        QVERIFY(!document_->isModified()); // view state, not the document's
        QVERIFY(document_->selection().empty()); // the drag did not pick
        const QRectF region(from, to);

        const QImage early = view.grabFramebuffer().convertToFormat(QImage::Format_RGB32);
        const int earlySamples = view.stats().samples;
        QVERIFY(waitFor([&] { return view.stats().samples >= earlySamples + 4; }));
        const QImage late = view.grabFramebuffer().convertToFormat(QImage::Format_RGB32);
        const Differences d = compare(early, late, region, view.size());
        qInfo("region: samples %d -> %d; changed pixels inside %d of %d, outside %d of %d", earlySamples,
              view.stats().samples, d.inside, d.insideCount, d.outside, d.outsideCount);
        QCOMPARE(d.outside, 0);                       // outside: the last image, bit for bit
        QVERIFY(d.inside > d.insideCount / 20);       // inside: still converging (over 5 % changed)

        // Clearing renders the whole view again: the outside changes while it converges.
        viewport_->clearRenderRegionAction()->trigger();
        QVERIFY(!view.renderRegion().has_value());
        const QImage first = view.grabFramebuffer().convertToFormat(QImage::Format_RGB32);
        const int firstSamples = view.stats().samples;
        QVERIFY(waitFor([&] { return view.stats().samples >= firstSamples + 4; }));
        const Differences cleared = compare(first, view.grabFramebuffer().convertToFormat(QImage::Format_RGB32), region, view.size());
        QVERIFY(cleared.outside > cleared.outsideCount / 20);
        QVERIFY(!document_->isModified());
    }

    // While the view moves the viewport renders the real-time configuration (SVGF, TAA) under
    // the scissor, at a coarser resolution: outside the region the last image stays (scaled to
    // that resolution once), so two moving frames of one resolution agree there.
    void regionKeepsTheOutsideWhileMoving() {
        RenderView& view = viewport_->view();
        QVERIFY(waitFor([&] { return view.stats().samples >= 2; }));
        const QRectF fractions(0.25, 0.25, 0.5, 0.5);
        view.setRenderRegion(fractions);
        const QRectF region(fractions.x() * view.width(), fractions.y() * view.height(), fractions.width() * view.width(),
                            fractions.height() * view.height());
        // Every paint's resolution divisor: a change in between rescales the outside.
        std::vector<int> divisors;
        const QMetaObject::Connection recording =
            connect(&view, &RenderView::statsChanged, this, [&] { divisors.push_back(view.stats().divisor); });
        const auto stopRecording = qScopeGuard([&] { disconnect(recording); }); // before `divisors` goes
        sendMouse(view, QEvent::MouseButtonPress, {64, 48}, Qt::MiddleButton, Qt::MiddleButton);
        QImage previous;
        int compared = 0;
        for (int i = 1; i <= 12 && compared < 2; ++i) {
            sendMouse(view, QEvent::MouseMove, QPointF(64 + 3 * i, 48), Qt::NoButton, Qt::MiddleButton);
            const std::size_t first = divisors.size();
            const QImage frame = view.grabFramebuffer().convertToFormat(QImage::Format_RGB32);
            QVERIFY2(view.stats().error.isEmpty(), qPrintable(view.stats().error));
            const bool sameSize = !previous.isNull() && first > 0 &&
                                  std::all_of(divisors.begin() + std::ptrdiff_t(first) - 1, divisors.end(),
                                              [&](int d) { return d == divisors.back(); });
            if (sameSize) {
                // At 1/d resolution the region covers whole coarse pixels (rounded outwards), and
                // the frame is scaled up bilinearly: its edge lies up to 1.5 d pixels further out.
                const int border = kBorder + 2 * divisors.back();
                const Differences d = compare(previous, frame, region, view.size(), border);
                QCOMPARE(d.outside, 0);
                QVERIFY(d.inside > d.insideCount / 20); // the orbit turned the view inside
                ++compared;
            }
            previous = frame;
            if (!divisors.empty()) divisors.erase(divisors.begin(), divisors.end() - 1); // keep the last paint's
        }
        sendMouse(view, QEvent::MouseButtonRelease, {100, 48}, Qt::MiddleButton, Qt::NoButton);
        QVERIFY(compared >= 1);
    }

    void regionFollowsAResize() {
        RenderView& view = viewport_->view();
        QVERIFY(waitFor([&] { return view.stats().samples >= 2 && !view.stats().filtering; })); // the filtered mean shown
        const QImage before = view.grabFramebuffer().convertToFormat(QImage::Format_RGB32);
        view.setRenderRegion(QRectF(0.5, 0.0, 0.5, 0.5));
        window_->resize(160, 120); // before the region's first frame: the last image must survive both
        QVERIFY(waitFor([&] { return view.width() > 128; }));
        QCOMPARE(*view.renderRegion(), QRectF(0.5, 0.0, 0.5, 0.5)); // fractions: proportional
        QVERIFY(waitFor([&] { return view.stats().samples >= 3; }));
        QVERIFY(view.stats().error.isEmpty());
        const QImage after = view.grabFramebuffer().convertToFormat(QImage::Format_RGB32);
        // Outside: the last image, scaled to the new size (within the blur of the scaling);
        // inside, top right: the grey sky rendered anew.
        const QRgb was = before.pixel(before.width() / 4, before.height() * 3 / 4);
        const QRgb is = after.pixel(after.width() / 4, after.height() * 3 / 4);
        QVERIFY2(std::abs(qGreen(was) - qGreen(is)) <= 24, qPrintable(QStringLiteral("%1 -> %2").arg(qGreen(was)).arg(qGreen(is))));
        QVERIFY(qGreen(after.pixel(after.width() * 3 / 4, 4)) > 100);
    }

    void heatMapShowsCostWithALegend() {
        RenderView& view = viewport_->view();
        test::addGridMesh(*document_, 8);
        view.setMode(ViewMode::BvhCost);
        QVERIFY(waitFor([&] { return view.stats().samples >= 2; }));
        QVERIFY2(view.stats().error.isEmpty(), qPrintable(view.stats().error));
        const QImage image = view.grabFramebuffer().convertToFormat(QImage::Format_RGB32);
        const auto grid = view.project({0.0, -0.4, 1.0});
        QVERIFY(grid);
        const QPoint onGrid = (*grid * image.width() / view.width()).toPoint();
        QCOMPARE(image.pixel(image.width() / 2, 2), qRgb(0, 0, 0)); // above everything: no BVH work
        QVERIFY(qRed(image.pixel(onGrid)) + qGreen(image.pixel(onGrid)) + qBlue(image.pixel(onGrid)) > 60);
        // The legend's colour bar (bottom right) runs up to the scale's red end.
        int reds = 0;
        for (int y = image.height() * 2 / 3; y < image.height(); ++y)
            for (int x = image.width() / 2; x < image.width(); ++x)
                reds += qRed(image.pixel(x, y)) > 200 && qGreen(image.pixel(x, y)) < 90;
        QVERIFY(reds > 0);
    }

private:
    std::unique_ptr<Document> document_;
    std::unique_ptr<QMainWindow> window_;
    Viewport* viewport_ = nullptr;
};

int main(int argc, char** argv) {
    glint::test::prepareGlApplication();
    QApplication app(argc, argv);
    TestViewportRegion test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_viewport_region.moc"
