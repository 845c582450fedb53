// Render regions (renderer/render_region.h, FrameRenderer): the pixels a region names, and the
// real-time filters at a region's edge. Cornell box, 96x96, seed 0, configuration Full (1 spp per
// frame, SVGF with 3 a-trous steps + TAA: a 21-pixel margin), region 32,32,32,32 (top-left origin).
//
// Before a region's frames, the renderer draws frames of another seed over the whole image, so
// that outside the region every target holds a stale picture, as in the editor. The region's
// frames are compared with frames of the whole image (same seed, same frame count from a reset):
// - the first frame bit for bit: the path-traced margin covers everything the filters read;
// - every frame up to the 8th within 1e-4 (max |difference| of RGBA over the region; radiance here
//   ~0.05-1): only history carries a trace of the outside, through the filters' weight tails.
// Measured on llvmpipe: frames 1-2 equal, frames 3-8 at most 1e-5 (edge and inside). Without the
// margin (the scissor on the region alone, the filters reading the stale outside): 0.024 at the
// edge on frame 1, up to 0.10 (edge) and 0.010 (inside) over 8 frames.
#include "renderer/frame_renderer.h"
#include "renderer/gl/headless_context.h"
#include "renderer/passes/region_composite.h"
#include "scene/io/scene_io.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>

using namespace glint;

namespace {

constexpr int kSize = 96;
constexpr renderer::ImageWindow kWindow{32, 32, 32, 32};
constexpr int kIterations = 3; // a-trous steps: the margin is 2 (2^3 - 1) + 3 + 3 + 1 = 21 pixels
constexpr int kFrames = 8;
constexpr double kHistoryTolerance = 1e-4;

// With 3 a-trous steps, so that the margin (21) leaves an outside of 11 pixels around it.
Scene cornell() {
    Scene scene = loadScene(std::filesystem::path(GLINT_RESOURCES_DIR) / "scenes" / "cornell_box" / "cornell_box.gltf").scene;
    scene.settings.render.svgf.iterations = kIterations;
    return scene;
}

renderer::FrameSettings fullSettings(std::uint32_t seed) {
    renderer::FrameSettings s;
    s.configuration = renderer::Configuration::Full;
    s.seed = seed;
    s.width = s.height = kSize;
    return s;
}

struct EdgeError {
    double edge = 0.0;     // max |difference| over the region's pixels within 4 of its edge
    double interior = 0.0; // and over the rest of the region
    bool bitEqual = true;
};

EdgeError compareInWindow(const std::vector<float>& region, const std::vector<float>& full) {
    EdgeError e;
    for (int y = kWindow.y; y < kWindow.y + kWindow.height; ++y)
        for (int x = kWindow.x; x < kWindow.x + kWindow.width; ++x) {
            const int inset = std::min({x - kWindow.x, y - kWindow.y, kWindow.x + kWindow.width - 1 - x,
                                        kWindow.y + kWindow.height - 1 - y});
            for (int c = 0; c < 4; ++c) {
                const std::size_t i = (std::size_t(y) * kSize + std::size_t(x)) * 4 + std::size_t(c);
                const double d = std::abs(double(region[i]) - double(full[i]));
                e.bitEqual = e.bitEqual && std::memcmp(&region[i], &full[i], sizeof(float)) == 0;
                (inset < 4 ? e.edge : e.interior) = std::max(inset < 4 ? e.edge : e.interior, d);
            }
        }
    return e;
}

} // namespace

class TestRenderRegion : public QObject {
    Q_OBJECT
private slots:
    // --region's whole pixels become fractions and back without gaining or losing a row.
    void windowsRoundTripThroughFractions() {
        for (const int size : {1, 3, 64, 333, 1080, 4097, 16384})
            for (const int x : {0, 1, size / 3, size - 1})
                for (const int w : {1, 2, size / 2, size - x}) {
                    if (w < 1 || x + w > size) continue;
                    const renderer::ImageWindow window{x, x, w, w};
                    const auto pixels = renderer::regionPixels(renderer::regionOfWindow(window, size, size), size, size);
                    QVERIFY2(renderer::imageWindowOf(pixels, size) == window,
                             qPrintable(QString("image %1: window %2,%2,%3,%3").arg(size).arg(x).arg(w)));
                }
    }

    void reachFollowsTheFilters() {
        using renderer::Configuration;
        QCOMPARE(renderer::reconstructionReach(renderer::traitsOf(Configuration::Reference), 5), 0);
        // SVGF's chain (1 + 62 + 3 + 3 = 69 px) and TAA's (1 + 3) lie inside the mean denoiser's 76 px.
        QCOMPARE(renderer::reconstructionReach(renderer::traitsOf(Configuration::Full), 5), 76);
        QCOMPARE(renderer::reconstructionReach(renderer::traitsOf(Configuration::Realistic), 5), 76);
        QCOMPARE(renderer::reconstructionReach(renderer::traitsOf(Configuration::Full), 6), 1 + 126 + 3 + 3);
    }

    void filtersAtTheRegionEdgeMatchTheFullFrame() {
        gl::HeadlessContext context;
        const Scene scene = cornell();
        renderer::FrameRenderer frames;
        frames.setSettings(fullSettings(0));
        frames.setScene(scene);
        std::vector<std::vector<float>> full;
        for (int f = 0; f < kFrames; ++f) {
            frames.renderFrame();
            full.push_back(frames.readImages().radiance);
        }
        frames.setSettings(fullSettings(7)); // a stale picture everywhere
        for (int f = 0; f < 3; ++f) frames.renderFrame();

        renderer::FrameSettings region = fullSettings(0);
        region.region = renderer::regionOfWindow(kWindow, kSize, kSize);
        frames.setSettings(region);
        frames.resetHistory(); // frame and sample counters from 0, as for the full frames
        for (int f = 0; f < kFrames; ++f) {
            frames.renderFrame();
            const renderer::FrameImages images = frames.readImages();
            QVERIFY(images.window == kWindow);
            const EdgeError e = compareInWindow(images.radiance, full[std::size_t(f)]);
            qInfo("frame %d: max |region - full| at the edge %.3g, inside %.3g", f + 1, e.edge, e.interior);
            if (f == 0) QVERIFY2(e.bitEqual, "the region's first frame differs from the full frame's");
            QVERIFY2(e.edge <= kHistoryTolerance && e.interior <= kHistoryTolerance,
                     qPrintable(QString("frame %1: edge %2, inside %3").arg(f + 1).arg(e.edge).arg(e.interior)));
        }
    }
};

QTEST_APPLESS_MAIN(TestRenderRegion)
#include "test_render_region.moc"
