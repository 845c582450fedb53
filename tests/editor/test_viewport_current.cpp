// The viewport always shows the current scene at full resolution, in a real window under Xvfb
// (160x120 px, llvmpipe). Every sequence starts after the view has reached its sample cap (the
// state in which the edits of a person who looked at the image for a while arrive, and in which
// the view used to stay flat grey or stale): add a shape, delete it, undo, redo, a gizmo move and
// its undo, visibility, a resize, view modes, a material value, the environment intensity and the
// configuration. After each, without touching the camera, the view must reach the cap again within
// a bounded number of paints and then equal a render of the same document, camera, size and sample
// count by a FrameRenderer in the same context (tolerance: every pixel within 2 of 255 per
// channel; measured: identical). With the frame budget forced low it refines: a coarse preview,
// bands at full resolution, then samples, ending on the same image as the reference. Every view
// mode draws every sample model (2CylinderEngine's Solid view included).
#include "renderer/frame_renderer.h" // epoxy's GL header before Qt's

#include "editor_fixtures.h"
#include "test_viewport_scene.h"

#include "editor/document/edit_operations.h"
#include "editor/viewport/render_host.h"
#include "editor/viewport/render_view.h"
#include "editor/viewport/viewport.h"
#include "scene/history/asset_commands.h"
#include "scene/history/settings_commands.h"

#include <QDir>
#include <QElapsedTimer>
#include <QMainWindow>
#include <QMouseEvent>
#include <QtTest>

#include <algorithm>
#include <functional>
#include <map>
#include <set>

using namespace glint;
using namespace glint::editor;

namespace {

constexpr int kCap = 4;            // the viewport's sample cap in these tests
constexpr int kMaxPaints = 400;    // from an edit to the capped image again
constexpr int kMaxWaitMs = 30000;

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

// The largest per-channel difference, and how many pixels differ by more than `tolerance`.
struct ImageDifference {
    int largest = 0;
    int pixelsOver = 0;
};

ImageDifference difference(const QImage& a, const QImage& b, int tolerance) {
    ImageDifference d;
    const QImage x = a.convertToFormat(QImage::Format_RGB32), y = b.convertToFormat(QImage::Format_RGB32);
    if (x.size() != y.size()) return {255, x.width() * x.height()};
    for (int j = 0; j < x.height(); ++j)
        for (int i = 0; i < x.width(); ++i) {
            const QRgb p = x.pixel(i, j), q = y.pixel(i, j);
            const int worst = std::max({std::abs(qRed(p) - qRed(q)), std::abs(qGreen(p) - qGreen(q)), std::abs(qBlue(p) - qBlue(q))});
            d.largest = std::max(d.largest, worst);
            d.pixelsOver += worst > tolerance;
        }
    return d;
}

// The share of pixels equal to the image's most common colour: 1 for a flat image.
double flatShare(const QImage& image) {
    const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
    std::map<QRgb, int> counts;
    for (int j = 0; j < rgb.height(); ++j)
        for (int i = 0; i < rgb.width(); ++i) ++counts[rgb.pixel(i, j)];
    int most = 0;
    for (const auto& [colour, n] : counts) most = std::max(most, n);
    return double(most) / std::max(1, rgb.width() * rgb.height());
}

MaterialId addMaterial(Scene& scene, glm::vec3 colour) {
    Material m;
    m.baseColorFactor = glm::vec4(colour, 1.0f);
    m.metallicFactor = 0.0f;
    m.roughnessFactor = 0.6f;
    return scene.materials.add(m);
}

} // namespace

class TestViewportCurrent : public QObject {
    Q_OBJECT

    std::unique_ptr<Document> document_;
    std::unique_ptr<QMainWindow> window_;
    Viewport* viewport_ = nullptr;
    glint::test::ShapesScene shapes_;

    RenderView& view() { return viewport_->view(); }

    // `beforeShowing` runs once the viewport exists, before its first paint.
    void show(int width = 160, int height = 120, double budgetMs = 30.0, const std::function<void()>& beforeShowing = {}) {
        window_ = std::make_unique<QMainWindow>();
        viewport_ = new Viewport(*document_, window_.get());
        viewport_->setSampleCap(kCap);
        viewport_->view().setFrameBudget(budgetMs);
        if (beforeShowing) beforeShowing();
        window_->setCentralWidget(viewport_);
        window_->resize(width, height);
        window_->show();
        QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
    }

    // The same document, camera, size and sample count rendered by a FrameRenderer of its own in
    // the view's context: what the view must show (tonemapped RGBA8, top-down).
    QImage reference(int samples) {
        RenderView& v = view();
        const int w = int(std::lround(v.width() * v.devicePixelRatioF())), h = int(std::lround(v.height() * v.devicePixelRatioF()));
        const RenderSettings& project = document_->scene().settings.render;
        renderer::FrameSettings s;
        s.configuration = renderer::Configuration::Accumulate;
        s.spp = 1;
        s.maxSamples = samples;
        s.bounces = project.bounces;
        s.seed = project.seed;
        s.exposure = project.exposure;
        s.clamp = project.clamp;
        s.denoise = v.denoise();
        s.width = w;
        s.height = h;
        v.makeCurrent();
        renderer::FrameImages images;
        {
            renderer::FrameRenderer r;
            r.setSettings(s);
            r.setScene(document_->scene());
            r.setCamera(cameraSetupOf(v.camera(), w, h));
            for (int i = 0; i < samples; ++i) r.renderFrame();
            images = r.readImages();
        }
        v.doneCurrent();
        return QImage(images.tonemapped.data(), images.width, images.height, QImage::Format_RGBA8888).copy();
    }

    // After an edit: the view reaches the cap again within kMaxPaints paints, never shows a flat
    // image on the way, and then equals the reference.
    void expectCurrent(const char* what) {
        RenderView& v = view();
        const long long start = v.stats().paints;
        bool flat = false;
        const auto capped = [&] {
            const ViewportStats& s = v.stats();
            return s.paints > start && s.stage == ViewStage::Converged && s.samples == kCap && s.divisor == 1;
        };
        QVERIFY2(waitFor([&] {
                     if (v.stats().paints > start && v.stats().paints - start < 4 && !v.stats().preparing)
                         flat = flat || flatShare(v.grabFramebuffer()) > 0.9;
                     return capped();
                 }),
                 qPrintable(QStringLiteral("%1: not capped again (stage %2, samples %3, error '%4')")
                                .arg(what).arg(int(v.stats().stage)).arg(v.stats().samples).arg(v.stats().error)));
        const long long paints = v.stats().paints - start;
        const QImage shown = v.grabFramebuffer();
        const ImageDifference d = difference(shown, reference(kCap), 2);
        qInfo("%s: capped after %lld paints; largest difference %d, %d pixels over 2", what, paints, d.largest, d.pixelsOver);
        QVERIFY2(!flat, what);
        QVERIFY(paints <= kMaxPaints);
        QVERIFY2(d.pixelsOver == 0, what);
        QVERIFY2(flatShare(shown) < 0.9, what);
    }

    void capped() {
        QVERIFY2(waitFor([&] { return view().stats().stage == ViewStage::Converged && view().stats().samples == kCap; }),
                 "the first image never reached the cap");
    }

private slots:
    void init() {
        document_ = std::make_unique<Document>();
        shapes_ = glint::test::buildShapesScene(*document_);
        Scene& scene = document_->scene();
        const MaterialId red = addMaterial(scene, {0.7f, 0.1f, 0.1f}), grey = addMaterial(scene, glm::vec3(0.5f));
        for (const auto& [node, material] : {std::pair{shapes_.sphere, red}, {shapes_.box, grey}, {shapes_.ground, grey}}) {
            Shape shape = *scene.at(node).get<Shape>();
            shape.material = material;
            scene.setComponent(node, shape);
        }
        document_->history().setClean();
    }
    void cleanup() {
        window_.reset();
        document_.reset();
    }

    void structuralEditsAfterTheCap() {
        show();
        capped();
        QVERIFY(addNode(*document_, QStringLiteral("Sphere"), defaultShape(ShapeKind::Sphere)).isEmpty());
        const NodeId added = document_->currentNode();
        QVERIFY(document_->scene().at(added).get<Shape>()->material.valid()); // a material the panel shows
        document_->setSelection({}); // no gizmo over the image
        expectCurrent("add a sphere");
        document_->setSelection({added});
        QVERIFY(deleteSelection(*document_).isEmpty());
        expectCurrent("delete it");
        document_->undo();
        document_->setSelection({});
        expectCurrent("undo the delete");
        document_->redo();
        expectCurrent("redo the delete");
        QVERIFY(setVisible(*document_, shapes_.sphere, false).isEmpty());
        expectCurrent("hide the red sphere");
        QVERIFY(setVisible(*document_, shapes_.sphere, true).isEmpty());
        expectCurrent("show it again");
    }

    // With adaptive sampling on, the view stops once every pixel has converged, well before its
    // sample cap, says so, and an edit starts it again.
    void adaptiveSamplingStopsTheViewBeforeTheCap() {
        ProjectSettings settings = document_->scene().settings;
        settings.render.adaptive = {.threshold = 0.5f, .minSamples = 2};
        document_->push(std::make_unique<SetProjectSettings>(settings));
        constexpr int kLargeCap = 100000;
        QString status;
        show(160, 120, 30.0, [&] {
            viewport_->setSampleCap(kLargeCap);
            connect(viewport_, &Viewport::statusMessage, this, [&status](const QString& text) { status = text; });
        });
        RenderView& v = view();
        const auto stopped = [&] { return v.stats().stage == ViewStage::NoiseConverged; };
        QVERIFY2(waitFor(stopped, 60000), qPrintable(QStringLiteral("never converged (stage %1, %2 spp)")
                                                         .arg(int(v.stats().stage)).arg(v.stats().samples)));
        const int samples = v.stats().samples;
        QVERIFY(samples >= 2 && samples < kLargeCap);
        QCOMPARE(v.stats().convergedPercent, 100);
        QVERIFY(waitFor([&] { return status.contains(QStringLiteral("converged (noise threshold)")); }));
        const QImage before = v.grabFramebuffer();
        const MaterialId sphereMaterial = document_->scene().at(shapes_.sphere).get<Shape>()->material;
        Material blue = document_->scene().materials.at(sphereMaterial);
        blue.baseColorFactor = glm::vec4(0.1f, 0.2f, 0.8f, 1.0f);
        document_->push(std::make_unique<SetMaterial>(sphereMaterial, blue));
        const long long start = v.stats().paints;
        QVERIFY2(waitFor([&] { return v.stats().paints > start && stopped(); }, 60000), "the edit did not converge again");
        QVERIFY(v.stats().samples < kLargeCap);
        QVERIFY2(difference(v.grabFramebuffer(), before, 2).pixelsOver > 100, "the converged view did not show the edit");
    }

    void gizmoMoveAndUndoAfterTheCap() {
        show();
        capped();
        RenderView& v = view();
        document_->setSelection({shapes_.box});
        const GizmoFrame frame = v.gizmoFrame(shapes_.box);
        const auto handle = v.project(frame.origin + 0.8 * frame.size * frame.axes[0]);
        QVERIFY(handle);
        sendMouse(v, QEvent::MouseButtonPress, *handle, Qt::LeftButton, Qt::LeftButton);
        for (int i = 1; i <= 4; ++i)
            sendMouse(v, QEvent::MouseMove, *handle + QPointF(-6.0 * i, 0.0), Qt::NoButton, Qt::LeftButton);
        sendMouse(v, QEvent::MouseButtonRelease, *handle + QPointF(-24.0, 0.0), Qt::LeftButton, Qt::NoButton);
        QVERIFY2(document_->canUndo(), "the gizmo drag moved nothing");
        document_->setSelection({});
        expectCurrent("move the box with the gizmo"); // capped only once the drag has settled
        document_->undo();
        document_->setSelection({});
        expectCurrent("undo the move");
        document_->redo();
        document_->setSelection({});
        expectCurrent("redo the move");
    }

    void valuesModesAndSizeAfterTheCap() {
        show();
        capped();
        Material red = document_->scene().materials.at(document_->scene().at(shapes_.sphere).get<Shape>()->material);
        red.baseColorFactor = glm::vec4(0.1f, 0.2f, 0.8f, 1.0f);
        document_->push(std::make_unique<SetMaterial>(document_->scene().at(shapes_.sphere).get<Shape>()->material, red));
        expectCurrent("the sphere's base colour");
        ProjectSettings settings = document_->scene().settings;
        settings.environment.intensity = 0.5f;
        document_->push(std::make_unique<SetProjectSettings>(settings));
        expectCurrent("the environment's intensity");
        settings.render.configuration = "full"; // the renders' configuration: a new GPU scene, the same picture
        document_->push(std::make_unique<SetProjectSettings>(settings));
        expectCurrent("the configuration");
        settings.render.bounces = settings.render.bounces + 1; // a render setting that changes the picture
        document_->push(std::make_unique<SetProjectSettings>(settings));
        expectCurrent("the bounce count");
        window_->resize(200, 150);
        QVERIFY(waitFor([&] { return view().width() > 170; }));
        expectCurrent("a resize");
        view().setMode(ViewMode::Solid);
        const long long paints = view().stats().paints;
        QVERIFY(waitFor([&] { return view().stats().paints > paints; }));
        QVERIFY(flatShare(view().grabFramebuffer()) < 0.9);
        view().setMode(ViewMode::PathTraced);
        expectCurrent("Solid, then Path traced again");
    }

    // With a 1 ms budget nothing whole fits a paint: a coarse preview first, then full-resolution
    // bands, then samples; the capped image is the reference's, so refinement never changes pixels.
    void refinesToFullResolutionOnASlowBudget() {
        document_ = std::make_unique<Document>();
        std::set<ViewStage> stages;
        std::set<int> coarseDivisors;
        show(160, 120, 1.0, [&] {
            connect(&view(), &RenderView::statsChanged, this, [&] {
                const ViewportStats& s = view().stats();
                if (s.moving || s.preparing) return; // opening moves the view to the scene's camera
                stages.insert(s.stage);
                if (s.stage == ViewStage::Coarse) coarseDivisors.insert(s.divisor);
            });
        });
        QVERIFY(document_->open(editor::test::cornellBox()).isEmpty()); // the view looks through its camera
        capped();
        disconnect(&view(), &RenderView::statsChanged, this, nullptr);
        QVERIFY(stages.count(ViewStage::Coarse));
        QVERIFY(stages.count(ViewStage::Refining));
        QVERIFY(stages.count(ViewStage::Accumulating));
        QVERIFY(*coarseDivisors.rbegin() > 1); // the preview was at a reduced resolution
        QCOMPARE(view().stats().divisor, 1);
        const QImage shown = view().grabFramebuffer(), expected = reference(kCap);
        shown.save(QStringLiteral(GLINT_TEST_OUTPUT_DIR "/viewport_refined.png"));
        expected.save(QStringLiteral(GLINT_TEST_OUTPUT_DIR "/viewport_refined_reference.png"));
        const ImageDifference d = difference(shown, expected, 2);
        qInfo("refined Cornell box: largest difference %d, %d pixels over 2", d.largest, d.pixelsOver);
        QCOMPARE(d.pixelsOver, 0);
    }

    // Each sample model in each view mode shows something (not one flat colour). The motion view of
    // a still camera is flat by design (no motion) and is left out.
    void everyViewModeDrawsEverySampleModel() {
        const QDir models(QStringLiteral(GLINT_TEST_DATA_DIR "/gltf"));
        QStringList files;
        for (const QString& folder : models.entryList(QDir::Dirs | QDir::NoDotAndDotDot))
            for (const QFileInfo& f : QDir(models.filePath(folder)).entryInfoList({"*.gltf", "*.glb"}, QDir::Files))
                files << f.filePath();
        for (const QFileInfo& f : QDir(models.filePath("2CylinderEngine")).entryInfoList({"*.glb"}, QDir::Files)) files << f.filePath();
        files.removeDuplicates();
        QVERIFY(files.size() >= 5);
        QVERIFY(files.filter("2CylinderEngine").size() == 1);
        document_ = std::make_unique<Document>();
        show(128, 96);
        viewport_->setSampleCap(2); // the variance view needs two samples
        for (const QString& file : files) {
            QVERIFY2(document_->open(file).isEmpty(), qPrintable(file));
            ProjectSettings settings = document_->scene().settings;
            settings.environment.color = glm::vec3(0.6f, 0.7f, 0.8f); // light for the assets that bring none
            document_->push(std::make_unique<SetProjectSettings>(settings));
            for (const ViewMode mode : kViewModes) {
                if (mode == ViewMode::Motion) continue;
                view().setMode(mode);
                const long long paints = view().stats().paints;
                const bool raster = showsRaster(mode);
                QVERIFY2(waitFor([&] {
                             const ViewportStats& s = view().stats();
                             return s.paints > paints && (raster || (s.stage == ViewStage::Converged && s.samples >= 2));
                         }),
                         qPrintable(QStringLiteral("%1, mode %2: no image").arg(file).arg(int(mode))));
                QVERIFY2(raster || view().stats().error.isEmpty(), qPrintable(view().stats().error));
                if (raster) QTest::qWait(20); // the click picker arrives: the depth range follows the scene
                view().update();
                const double flat = flatShare(view().grabFramebuffer());
                QVERIFY2(flat < 0.995, qPrintable(QStringLiteral("%1, mode %2: flat (%3)").arg(file).arg(int(mode)).arg(flat)));
            }
        }
    }
};

int main(int argc, char** argv) {
    glint::test::prepareGlApplication();
    QApplication app(argc, argv);
    TestViewportCurrent test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_viewport_current.moc"
