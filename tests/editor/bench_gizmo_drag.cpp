// A benchmark program (not a test) for docs/PERFORMANCE.md: what one frame of a gizmo drag costs the
// GUI thread on a large mesh scene (the Cornell box with 16 Stanford bunnies, 1.1 M triangles
// instanced; with `unique`, each bunny a mesh of its own, so the document holds 1.1 M triangles). A real viewport in a real window (an X display: Xvfb will do) drags a bunny along X
// with the move gizmo; for every mouse move it measures the time from the event to the end of the
// paint that shows it (the command, the in-place GPU update, one real-time frame), the renderer's
// in-place update alone, and what copying the document costs (the renderer keeps a copy per edit).
//
//   bench_gizmo_drag BUNNY.obj [MOVES] [unique]
#include "test_viewport_scene.h"

#include "app/bench/bench_scenes.h"
#include "app/bench/percentile.h"
#include "editor/viewport/render_view.h"
#include "editor/viewport/viewport.h"
#include "scene/io/scene_io.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QMainWindow>
#include <QMouseEvent>
#include <QTest>

#include <cstdio>
#include <vector>

using namespace glint;
using namespace glint::editor;

namespace {

void sendMouse(QWidget& w, QEvent::Type type, QPointF at, Qt::MouseButton button, Qt::MouseButtons buttons) {
    QMouseEvent event(type, at, w.mapToGlobal(at), button, buttons, Qt::NoModifier);
    QCoreApplication::sendEvent(&w, &event);
}

// Bytes of vertex, index and image data the scene holds.
std::size_t payloadBytes(const Scene& scene) {
    std::size_t bytes = 0;
    for (const auto& [id, mesh] : scene.meshes)
        for (const Primitive& p : mesh.primitives)
            bytes += p.positions.size() * sizeof(glm::vec3) + p.normals.size() * sizeof(glm::vec3) +
                     p.tangents.size() * sizeof(glm::vec4) + (p.uv0.size() + p.uv1.size()) * sizeof(glm::vec2) +
                     p.colors.size() * sizeof(glm::vec4) + p.indices.size() * sizeof(std::uint32_t);
    for (const auto& [id, image] : scene.images) bytes += image.encoded.size();
    return bytes;
}

double ms(const QElapsedTimer& t) { return double(t.nsecsElapsed()) / 1e6; }

} // namespace

int main(int argc, char** argv) {
    test::prepareGlApplication();
    QApplication app(argc, argv);
    const QStringList args = app.arguments();
    if (args.size() < 2) {
        std::fprintf(stderr, "usage: bench_gizmo_drag BUNNY.obj [MOVES]\n");
        return 2;
    }
    const int moves = args.size() > 2 ? args[2].toInt() : 40;
    const LoadResult cornell = loadScene(GLINT_RESOURCES_DIR "/scenes/cornell_box/cornell_box.gltf");
    Scene scene = bench::benchScenes(cornell.scene, args[1].toStdString()).back().scene; // 16 bunnies
    if (args.size() > 3 && args[3] == QLatin1String("unique")) { // each instance its own copy of the mesh
        for (const NodeId id : scene.depthFirst()) {
            const auto* instance = scene.at(id).get<MeshInstance>();
            if (!instance || scene.at(id).name.rfind("bunny_", 0) != 0) continue;
            MeshInstance own = *instance;
            own.mesh = scene.meshes.add(Mesh(scene.meshes.at(instance->mesh)));
            scene.setComponent(id, own);
        }
    }
    const std::size_t triangles = bench::visibleTriangles(scene);

    std::vector<double> copyMs;
    for (int i = 0; i < 10; ++i) {
        QElapsedTimer t;
        t.start();
        const Scene copy = scene;
        copyMs.push_back(ms(t));
        if (copy.nodeCount() != scene.nodeCount()) return 1;
    }

    Document document;
    document.scene() = std::move(scene);
    QMainWindow window;
    auto* viewport = new Viewport(document, &window);
    viewport->setSampleCap(1);
    window.setCentralWidget(viewport);
    viewport->view().setFixedSize(640, 360);
    window.show();
    if (!QTest::qWaitForWindowExposed(&window)) return 1;
    RenderView& view = viewport->view();
    view.frameSelection();
    while (view.stats().stage != ViewStage::Converged) QTest::qWait(10);

    const auto bunny = document.scene().findByName("bunny_5");
    if (!bunny) return 1;
    document.setSelection({*bunny});
    view.update();
    QTest::qWait(50);
    const GizmoFrame frame = view.gizmoFrame(*bunny);
    const auto handle = view.project(frame.origin + 0.8 * frame.size * frame.axes[0]);
    if (!handle) return 1;
    sendMouse(view, QEvent::MouseButtonPress, *handle, Qt::LeftButton, Qt::LeftButton);
    std::vector<double> frameMs, inPlaceMs;
    for (int i = 1; i <= moves; ++i) {
        const long long paints = view.stats().paints;
        QElapsedTimer t;
        t.start();
        sendMouse(view, QEvent::MouseMove, *handle + QPointF(i % 2 ? 2.0 : -2.0, 0.0), Qt::NoButton, Qt::LeftButton);
        while (view.stats().paints == paints) QCoreApplication::processEvents(QEventLoop::AllEvents, 1);
        frameMs.push_back(ms(t));
        inPlaceMs.push_back(view.stats().inPlaceMs);
    }
    sendMouse(view, QEvent::MouseButtonRelease, *handle, Qt::LeftButton, Qt::NoButton);
    std::printf("16 bunnies (%zu triangles instanced, %.1f MB of vertex and index data): a scene copy %.2f ms "
                "(median of 10); per drag frame (median of %d, p90): event to painted %.1f ms (%.1f), renderer "
                "in-place update %.2f ms (%.2f)\n",
                triangles, double(payloadBytes(document.scene())) / 1e6, bench::percentile(copyMs, 0.5), moves,
                bench::percentile(frameMs, 0.5), bench::percentile(frameMs, 0.9), bench::percentile(inPlaceMs, 0.5),
                bench::percentile(inPlaceMs, 0.9));
    return 0;
}
