// A benchmark program (not a test) for docs/PERFORMANCE.md: how long the editor takes from File >
// Open to the first path-traced pixel on screen, and where the time goes.
//
//   bench_first_pixel SCENE [WIDTHxHEIGHT]
//
// The main window with its viewport, in a real window (an X display: Xvfb will do), opens SCENE the
// way File > Open does (read on a worker, the GPU scene prepared on another) and prints, in ms from
// the open: the document holding the scene, the GPU scene uploaded, the first path-traced frame
// painted (coarse), the first full-resolution sample. One open per process, so every run is cold
// (no mesh BVH or texture cache from an earlier open); run it several times for a median.
#include "editor/document/document.h"
#include "editor/main_window/main_window.h"
#include "editor/viewport/render_view.h"
#include "editor/viewport/viewport.h"
#include "window_options.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QTemporaryDir>
#include <QTest>

#include <cstdio>

using namespace glint::editor;

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    const QStringList args = app.arguments();
    if (args.size() < 2) {
        std::fprintf(stderr, "usage: bench_first_pixel SCENE [WIDTHxHEIGHT]\n");
        return 2;
    }
    const QStringList size = args.value(2, QStringLiteral("1280x720")).split('x');
    QTemporaryDir autosave;
    MainWindow window(test::windowOptions(autosave.path()));
    window.resize(size.value(0).toInt(), size.value(1).toInt());
    window.show();
    if (!QTest::qWaitForWindowExposed(&window)) return 1;
    RenderView& view = window.viewport()->view();
    QElapsedTimer shown;
    shown.start();
    while ((view.stats().preparing || view.stats().paints == 0) && shown.elapsed() < 30000) QTest::qWait(5); // the empty scene
    const int uploadsBefore = view.stats().uploads;

    QElapsedTimer clock;
    double loaded = -1, uploaded = -1, firstFrame = -1, fullResolution = -1;
    QStringList stages; // the preparation's progress lines, each with the time it first showed
    QObject::connect(&window.document(), &Document::loaded, [&] { loaded = double(clock.nsecsElapsed()) * 1e-6; });
    QObject::connect(&view, &RenderView::statsChanged, [&] {
        const ViewportStats& s = view.stats();
        const double now = double(clock.nsecsElapsed()) * 1e-6;
        const QString stage = s.preparation.section(':', 0, 1);
        if (s.preparing && !stage.isEmpty() && (stages.isEmpty() || !stages.last().endsWith(stage)))
            stages << QStringLiteral("%1 ms %2").arg(now, 0, 'f', 0).arg(stage);
        if (s.uploads == uploadsBefore || s.preparing) return;
        if (uploaded < 0) uploaded = now;
        if (firstFrame < 0 && s.paints > 0 && s.stage != ViewStage::Preparing) firstFrame = now;
        if (fullResolution < 0 && s.divisor == 1 && s.samples >= 1) fullResolution = now;
    });
    clock.start();
    window.document().startOpen(args[1]);
    while (fullResolution < 0 && clock.elapsed() < 600000) QTest::qWait(1);
    std::printf("%s: document %.0f ms, GPU scene uploaded %.0f ms, first path-traced frame %.0f ms, "
                "first full-resolution sample %.0f ms (-1: not reached)\n",
                qPrintable(args[1]), loaded, uploaded, firstFrame, fullResolution);
    std::printf("  preparation on the worker %.0f ms; its stages as the status bar showed them:\n", view.stats().prepareMs);
    for (const QString& line : stages) std::printf("    %s\n", qPrintable(line));
    window.document().history().setClean(); // no unsaved-changes prompt
    return fullResolution < 0 ? 1 : 0;
}
