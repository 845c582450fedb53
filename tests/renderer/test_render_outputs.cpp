// What a render hands back: tonemapped sRGB bytes with documented rounding, the AOVs (depth, normal,
// object id, albedo), the ambient-occlusion debug view, and the refusal of software GL on request.
#include "image_stats.h"
#include "scene_builder.h"

#include "renderer/gl/headless_context.h"
#include "renderer/offline_render.h"
#include "renderer/output/tonemap_cpu.h"

#include <QTest>

#include <cmath>
#include <memory>

using namespace glint;
using namespace glint::test;

class TestRenderOutputs : public QObject {
    Q_OBJECT
    std::unique_ptr<renderer::OfflineRenderer> renderer_;

    renderer::RenderOutput render(const Scene& scene, Tonemapper tonemapper, float exposure,
                                  renderer::DebugView view = renderer::DebugView::None) {
        renderer::RenderRequest request;
        request.width = 8;
        request.height = 8;
        request.spp = 2;
        request.seed = 5;
        request.tonemapper = tonemapper;
        request.exposure = exposure;
        request.view = view;
        return renderer_->render(scene, request);
    }

    // A camera looking into a uniform sky of radiance `sky` and nothing else.
    static Scene sky(glm::vec3 radiance) {
        Scene scene;
        scene.settings.environment.color = radiance;
        addPerspectiveCamera(scene, glm::vec3(0.0f), {0.0f, 0.0f, -1.0f}, 0.5f);
        return scene;
    }

private slots:
    void initTestCase() { renderer_ = std::make_unique<renderer::OfflineRenderer>(); }
    void cleanupTestCase() { renderer_.reset(); }

    // 8x8, 2 spp, seed 5. Linear radiance r -> exposure 2^EV -> curve -> sRGB -> round(x * 255):
    // 0.5 with no curve is 188 (sRGB 0.7354); +1 EV saturates at 255; PBR Neutral maps 0.18 to
    // 0.14 (sRGB 0.4100, byte 105). The published curves, evaluated by hand (double precision):
    // AgX (minimal AgX: inset matrix, log2 in [-12.47393, 4.026069], the 6th-order contrast fit,
    // outset matrix, ^2.2) takes 0.18 to 0.2139 (128) and 1 to 0.589 (202); Reinhard extended (white
    // 4) takes 0.18 to 0.1543 (109) and 4 to exactly 1 (255); Hable (bias 2, white 11.2) takes 0.18 to
    // 0.1283 (100) and 5.6 to exactly 1 (255). Alpha is coverage: 255.
    void tonemappedBytes_data() {
        QTest::addColumn<float>("radiance");
        QTest::addColumn<int>("tonemapper");
        QTest::addColumn<float>("exposure");
        QTest::addColumn<int>("expected");
        QTest::newRow("none, 0.5") << 0.5f << int(Tonemapper::None) << 0.0f << 188;
        QTest::newRow("none, 0.5 at +1 EV") << 0.5f << int(Tonemapper::None) << 1.0f << 255;
        QTest::newRow("none, 0.0") << 0.0f << int(Tonemapper::None) << 0.0f << 0;
        QTest::newRow("PBR Neutral, 0.18") << 0.18f << int(Tonemapper::PbrNeutral) << 0.0f << 105;
        QTest::newRow("AgX, 0.18") << 0.18f << int(Tonemapper::AgX) << 0.0f << 128;
        QTest::newRow("AgX, 1.0") << 1.0f << int(Tonemapper::AgX) << 0.0f << 202;
        QTest::newRow("AgX, 0.0") << 0.0f << int(Tonemapper::AgX) << 0.0f << 0;
        QTest::newRow("Reinhard, 0.18") << 0.18f << int(Tonemapper::Reinhard) << 0.0f << 109;
        QTest::newRow("Reinhard, white 4") << 4.0f << int(Tonemapper::Reinhard) << 0.0f << 255;
        QTest::newRow("Hable, 0.18") << 0.18f << int(Tonemapper::Hable) << 0.0f << 100;
        QTest::newRow("Hable, white 11.2 / 2") << 5.6f << int(Tonemapper::Hable) << 0.0f << 255;
    }
    void tonemappedBytes() {
        QFETCH(float, radiance);
        QFETCH(int, tonemapper);
        QFETCH(float, exposure);
        QFETCH(int, expected);
        const auto out = render(sky(glm::vec3(radiance)), static_cast<Tonemapper>(tonemapper), exposure);
        QCOMPARE(out.radiance[0], radiance); // exposure and curve never touch the linear image
        for (std::size_t i = 0; i < out.tonemapped.size(); ++i)
            QCOMPARE(int(out.tonemapped[i]), i % 4 == 3 ? 255 : expected);
        // The CPU twin (videos from EXR frames) gives the same byte.
        const auto cpu = video::tonemapToSrgb8({radiance, radiance, radiance, 1.0f}, exposure, static_cast<Tonemapper>(tonemapper));
        QCOMPARE(int(cpu[0]), expected);
    }

    // 8x8: an orthographic camera 2 m above a ground plane: depth 2, normal +Y, id of the ground
    // node, albedo its base colour. The sky: depth +inf, id 0. A sphere lamp: its node's id.
    void aovsDescribeTheFirstHit() {
        Scene scene;
        const MaterialId grey = scene.materials.add(lambert({0.25f, 0.5f, 0.75f}));
        const NodeId ground = addShape(scene, ShapeKind::GroundPlane, grey, glm::vec3(0.0f));
        addOrthographicCamera(scene, {0.0f, 2.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 1.0f);
        const auto out = render(scene, Tonemapper::None, 0.0f);
        for (std::size_t p = 0; p < 64; ++p) {
            QCOMPARE(out.depth[p], 2.0f);
            QCOMPARE(out.objectId[p], float(ground.value));
            QCOMPARE(glm::vec3(out.normal[3 * p], out.normal[3 * p + 1], out.normal[3 * p + 2]), glm::vec3(0.0f, 1.0f, 0.0f));
            QCOMPARE(glm::vec3(out.albedo[3 * p], out.albedo[3 * p + 1], out.albedo[3 * p + 2]), glm::vec3(0.25f, 0.5f, 0.75f));
        }
        const auto empty = render(sky(glm::vec3(1.0f)), Tonemapper::None, 0.0f);
        QVERIFY(std::isinf(empty.depth[0]) && empty.depth[0] > 0.0f);
        QCOMPARE(empty.objectId[0], 0.0f);
        // A sphere lamp (radius 1 m, 1 m under the camera, filling the view) is a visible object
        // too: its node's id and its depth, as a mesh or shape would give.
        Light lamp;
        lamp.radius = 1.0f;
        const NodeId lampNode = addNode(scene, "lamp", lamp, {0.0f, 0.0f, 0.0f});
        const auto lit = render(scene, Tonemapper::None, 0.0f);
        for (std::size_t p : {std::size_t{27}, std::size_t{36}}) { // the pixels at the centre
            QCOMPARE(lit.objectId[p], float(lampNode.value));
            QVERIFY(lit.depth[p] > 1.0f && lit.depth[p] < 1.05f); // the lamp's top is 1 m away, its side a bit further
        }
    }

    // 8x8, 2 spp: ambient occlusion (1 m) of an open ground plane is exactly 1; inside a closed box
    // 0.5 m across, exactly 0.
    void ambientOcclusionView() {
        Scene scene;
        const MaterialId grey = scene.materials.add(lambert(glm::vec3(0.5f)));
        addShape(scene, ShapeKind::GroundPlane, grey, glm::vec3(0.0f));
        addOrthographicCamera(scene, {0.0f, 2.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 1.0f);
        QCOMPARE(channelStats(render(scene, Tonemapper::None, 0.0f, renderer::DebugView::AmbientOcclusion).radiance, 0).minimum, 1.0);
        addShape(scene, ShapeKind::Box, grey, {0.0f, 0.2f, 0.0f}, 0.5f, {0.5f, 0.6f, 0.5f});
        addOrthographicCamera(scene, {0.0f, 0.2f, 0.0f}, {0.0f, -1.0f, 0.0f}, 0.1f);
        scene.settings.activeCamera = NodeId(4);
        QCOMPARE(channelStats(render(scene, Tonemapper::None, 0.0f, renderer::DebugView::AmbientOcclusion).radiance, 0).maximum, 0.0);
    }

    // --require-gpu refuses a software rasteriser by name and accepts hardware.
    void requireGpuRefusesSoftware() {
        const bool software = gl::isSoftwareRenderer(renderer_->glRenderer());
        renderer_.reset(); // one context at a time
        try {
            renderer::OfflineRenderer strict(true);
            QVERIFY2(!software, "a software renderer was accepted");
        } catch (const std::runtime_error& e) {
            QVERIFY2(software, e.what());
            QVERIFY(QString(e.what()).startsWith("a GPU is required but OpenGL runs on the software renderer "));
        }
        renderer_ = std::make_unique<renderer::OfflineRenderer>();
    }
};

QTEST_APPLESS_MAIN(TestRenderOutputs)
#include "test_render_outputs.moc"
