// A benchmark program (not a test) for docs/PERFORMANCE.md: how long a still viewport takes, after
// the mouse is released, to show a full-resolution image and to reach its sample cap, and how long
// until what it shows is close to the converged image (SSIM 0.9), with the mean denoiser and without.
//
//   bench_viewport_refine SCENE [WIDTHxHEIGHT] [SAMPLES] [REFERENCE_SPP] [OUT.csv]
//
// Runs the editor's viewport in a real window (an X display: Xvfb will do). Phase 1 times the
// viewport itself: an orbit drag, the release, then each stage as the status bar reports it. Phase 2
// measures quality in the same GL context with a FrameRenderer of the same settings (the viewport
// shows exactly its image, tests/editor/test_viewport_current.cpp): relMSE and SSIM of the raw and
// the denoised mean at every sample count against a reference of REFERENCE_SPP samples. Each sample
// count is mapped to the time the viewport reached it.
#include "renderer/frame_renderer.h" // epoxy's GL header before Qt's

#include "test_viewport_scene.h"

#include "app/bench/image_metrics.h"
#include "editor/viewport/render_host.h"
#include "editor/viewport/render_view.h"
#include "editor/viewport/viewport.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QMainWindow>
#include <QMouseEvent>
#include <QTest>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

using namespace glint;
using namespace glint::editor;

namespace {

struct Options {
    QString scene;
    int width = 1280, height = 720, samples = 64, referenceSpp = 256;
    std::string out = "viewport_refine.csv";
};

void sendMouse(QWidget& w, QEvent::Type type, QPointF at, Qt::MouseButtons buttons, Qt::KeyboardModifiers mods) {
    QMouseEvent event(type, at, w.mapToGlobal(at), type == QEvent::MouseMove ? Qt::NoButton : Qt::LeftButton, buttons, mods);
    QCoreApplication::sendEvent(&w, &event);
}

// When the viewport reached each stage after the release (ms), and each sample count.
struct RefineTimeline {
    double fullResolution = -1.0; // the first full-resolution sample is whole
    std::map<int, double> samples; // as paints reported them (one paint may add several)
    // When the view first showed n samples or more; -1: never.
    double at(int n) const {
        const auto it = samples.lower_bound(n);
        return it == samples.end() ? -1.0 : it->second;
    }
};

RefineTimeline timeTheViewport(RenderView& view, int samples) {
    QElapsedTimer clock;
    RefineTimeline t;
    QObject::connect(&view, &RenderView::statsChanged, &view, [&] {
        if (!clock.isValid()) return;
        const ViewportStats& s = view.stats();
        if (s.divisor != 1 || s.samples < 1 || s.stage == ViewStage::Coarse) return;
        if (t.fullResolution < 0.0) t.fullResolution = double(clock.nsecsElapsed()) / 1e6;
        if (!t.samples.count(s.samples)) t.samples[s.samples] = double(clock.nsecsElapsed()) / 1e6;
    });
    // An orbit drag (Alt + left), then the release: the clock starts there.
    const QPointF centre(view.width() / 2.0, view.height() / 2.0);
    sendMouse(view, QEvent::MouseButtonPress, centre, Qt::LeftButton, Qt::AltModifier);
    for (int i = 1; i <= 5; ++i) {
        sendMouse(view, QEvent::MouseMove, centre + QPointF(2.0 * i, 0.0), Qt::LeftButton, Qt::AltModifier);
        QTest::qWait(20);
    }
    sendMouse(view, QEvent::MouseButtonRelease, centre + QPointF(10.0, 0.0), Qt::NoButton, Qt::AltModifier);
    clock.start();
    while (view.stats().samples < samples || view.stats().stage != ViewStage::Converged) QTest::qWait(2);
    QObject::disconnect(&view, &RenderView::statsChanged, &view, nullptr);
    return t;
}

renderer::FrameSettings stillSettings(const Scene& scene, int width, int height) {
    const RenderSettings& project = scene.settings.render;
    renderer::FrameSettings s;
    s.configuration = renderer::Configuration::Accumulate;
    s.spp = 1;
    s.bounces = project.bounces;
    s.seed = project.seed;
    s.clamp = project.clamp;
    s.width = width;
    s.height = height;
    return s;
}

struct Quality {
    double relmse = 0.0, ssim = 0.0;
};

// relMSE and SSIM of the mean at every sample count 1..samples, raw or denoised.
// `environment`: the project's image as the viewport reads it (Document::environmentPath()).
std::vector<Quality> measure(RenderView& view, const Scene& scene, const std::filesystem::path& environment,
                             const renderer::CameraSetup& camera, int samples, bool denoise, const std::vector<float>& reference,
                             int width, int height) {
    renderer::FrameRenderer r;
    renderer::FrameSettings s = stillSettings(scene, width, height);
    s.denoise = denoise;
    r.setSettings(s);
    r.setScene(scene, environment);
    r.setCamera(camera);
    std::vector<Quality> out;
    for (int n = 1; n <= samples; ++n) {
        r.renderFrame();
        const std::vector<float> image = r.readImages().radiance;
        out.push_back({bench::relMse(image, reference), bench::ssim(image, reference, width, height)});
    }
    (void)view;
    return out;
}

std::vector<float> referenceImage(const Scene& scene, const std::filesystem::path& environment, const renderer::CameraSetup& camera,
                                  int spp, int width, int height) {
    renderer::FrameRenderer r;
    renderer::FrameSettings s = stillSettings(scene, width, height);
    s.configuration = renderer::Configuration::Reference;
    s.spp = spp;
    s.seed = s.seed + 0x9e3779b9u; // other samples than the ones measured
    r.setSettings(s);
    r.setScene(scene, environment);
    r.setCamera(camera);
    r.renderFrame();
    return r.readImages().radiance;
}

double timeToSsim(const RefineTimeline& t, const std::vector<Quality>& q, double target) {
    for (std::size_t n = 0; n < q.size(); ++n)
        if (q[n].ssim >= target) return t.at(int(n) + 1);
    return -1.0;
}

} // namespace

int main(int argc, char** argv) {
    test::prepareGlApplication();
    QApplication app(argc, argv);
    const QStringList args = app.arguments();
    if (args.size() < 2) {
        std::fprintf(stderr, "usage: bench_viewport_refine SCENE [WxH] [SAMPLES] [REFERENCE_SPP] [OUT.csv]\n");
        return 2;
    }
    Options o;
    o.scene = args[1];
    if (args.size() > 2) {
        const QStringList size = args[2].split('x');
        o.width = size.value(0).toInt();
        o.height = size.value(1).toInt();
    }
    if (args.size() > 3) o.samples = args[3].toInt();
    if (args.size() > 4) o.referenceSpp = args[4].toInt();
    if (args.size() > 5) o.out = args[5].toStdString();

    Document document;
    QMainWindow window;
    auto* viewport = new Viewport(document, &window);
    viewport->setSampleCap(o.samples);
    window.setCentralWidget(viewport);
    viewport->view().setFixedSize(o.width, o.height);
    window.show();
    if (!QTest::qWaitForWindowExposed(&window)) return 1;
    if (const QString error = document.open(o.scene); !error.isEmpty()) {
        std::fprintf(stderr, "%s\n", qPrintable(error));
        return 1;
    }
    RenderView& view = viewport->view();
    while (view.stats().stage != ViewStage::Converged || view.stats().samples < 1) QTest::qWait(10); // opened and shown once
    const RefineTimeline t = timeTheViewport(view, o.samples);
    std::fprintf(stderr, "viewport: full resolution after %.0f ms, %d spp after %.0f ms\n", t.fullResolution, o.samples, t.at(o.samples));

    const qreal dpr = view.devicePixelRatioF();
    const int w = int(std::lround(o.width * dpr)), h = int(std::lround(o.height * dpr));
    const renderer::CameraSetup camera = cameraSetupOf(view.camera(), w, h);
    view.makeCurrent();
    std::fprintf(stderr, "reference: %d spp\n", o.referenceSpp);
    const std::filesystem::path environment = document.environmentPath();
    const std::vector<float> reference = referenceImage(document.scene(), environment, camera, o.referenceSpp, w, h);
    const std::vector<Quality> raw = measure(view, document.scene(), environment, camera, o.samples, false, reference, w, h);
    const std::vector<Quality> denoised = measure(view, document.scene(), environment, camera, o.samples, true, reference, w, h);
    view.doneCurrent();

    std::ofstream csv(o.out);
    csv << "samples,ms_after_release,relmse_raw,ssim_raw,relmse_denoised,ssim_denoised\n";
    for (int n = 1; n <= o.samples; ++n) {
        const double ms = t.at(n);
        csv << n << "," << ms << "," << raw[std::size_t(n - 1)].relmse << "," << raw[std::size_t(n - 1)].ssim << ","
            << denoised[std::size_t(n - 1)].relmse << "," << denoised[std::size_t(n - 1)].ssim << "\n";
    }
    std::printf("scene %s, %dx%d: full resolution %.0f ms after release, %d spp %.0f ms; SSIM 0.9: raw %.0f ms, denoised "
                "%.0f ms (-1: not reached)\n",
                qPrintable(o.scene), w, h, t.fullResolution, o.samples, t.at(o.samples),
                timeToSsim(t, raw, 0.9), timeToSsim(t, denoised, 0.9));
    return 0;
}
