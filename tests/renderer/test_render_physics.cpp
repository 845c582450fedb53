// Known-answer renders: white furnaces, a Lambert plane under the sun, a mirror and a glass slab.
// Each test states its size, spp, seed and tolerance. Scenes are built in code.
#include "image_stats.h"
#include "scene_builder.h"

#include "renderer/offline_render.h"

#include <QTest>

#include <cmath>
#include <memory>

using namespace glint;
using namespace glint::test;

class TestRenderPhysics : public QObject {
    Q_OBJECT
    std::unique_ptr<renderer::OfflineRenderer> renderer_;

    renderer::RenderOutput render(const Scene& scene, int size, int spp, std::uint32_t seed, int bounces) {
        renderer::RenderRequest request;
        request.width = size;
        request.height = size;
        request.spp = spp;
        request.seed = seed;
        request.bounces = bounces;
        request.tonemapper = Tonemapper::None;
        return renderer_->render(scene, request);
    }

    // A sphere of `albedo` inside a closed sphere (radius 5) of Lambert `wallAlbedo` emitting `wallEmission`.
    static Scene furnace(float albedo, float wallAlbedo, float wallEmission) {
        Scene scene;
        const MaterialId wall = scene.materials.add(lambert(glm::vec3(wallAlbedo), glm::vec3(wallEmission)));
        const MaterialId ball = scene.materials.add(lambert(glm::vec3(albedo)));
        addShape(scene, ShapeKind::Sphere, wall, glm::vec3(0.0f), 5.0f);
        addShape(scene, ShapeKind::Sphere, ball, glm::vec3(0.0f), 1.0f);
        addPerspectiveCamera(scene, {0.0f, 0.0f, 3.0f}, glm::vec3(0.0f), 0.8f);
        return scene;
    }

private slots:
    void initTestCase() { renderer_ = std::make_unique<renderer::OfflineRenderer>(); }
    void cleanupTestCase() { renderer_.reset(); }

    // 32x32, 256 spp, seed 1, 64 bounces (Russian roulette decides). Walls of albedo 0.5 emitting 0.5
    // around a white Lambert sphere: radiance is 1 everywhere (L = 0.5 + 0.5 L). Mean within 0.5 %,
    // every pixel within 4 sigma (sigma: the spread over the image, whose expected value is uniform).
    void whiteFurnaceIsOne() {
        const auto out = render(furnace(1.0f, 0.5f, 0.5f), 32, 256, 1, 64);
        for (int c = 0; c < 3; ++c) {
            const ChannelStats s = channelStats(out.radiance, c);
            QVERIFY2(std::abs(s.mean - 1.0) < 0.005, qPrintable(QString("channel %1 mean %2").arg(c).arg(s.mean)));
            QVERIFY2(s.minimum >= 1.0 - 4.0 * s.stddev && s.maximum <= 1.0 + 4.0 * s.stddev,
                     qPrintable(QString("range [%1, %2], sigma %3").arg(s.minimum).arg(s.maximum).arg(s.stddev)));
        }
    }

    // 32x32, 4 spp, seed 2, 4 bounces. Black walls emitting 1 around a sphere of albedo 0.5: the
    // sphere shows 0.5, the walls 1. Sphere pixels (centre 8x8) within 0.5 % of 0.5.
    void halfAlbedoFurnaceIsHalf() {
        const auto out = render(furnace(0.5f, 0.0f, 1.0f), 32, 4, 2, 4);
        for (int y = 12; y < 20; ++y)
            for (int x = 12; x < 20; ++x)
                QVERIFY2(std::abs(pixel(out.radiance, 32, x, y, 1) - 0.5f) < 0.0025f,
                         qPrintable(QString("pixel %1,%2 = %3").arg(x).arg(y).arg(pixel(out.radiance, 32, x, y, 1))));
        QCOMPARE(pixel(out.radiance, 32, 0, 0, 0), 1.0f);
    }

    // 16x16, 4 spp, seed 3, 0 bounces. A ground plane of albedo 0.8 under a sun of 1000 lux at 60
    // degrees from the normal: L = 0.8 / pi * 1000 / 683 * cos(60 deg), within 1 %.
    void lambertPlaneUnderSun() {
        Scene scene;
        const MaterialId ground = scene.materials.add(lambert(glm::vec3(0.8f)));
        addShape(scene, ShapeKind::GroundPlane, ground, glm::vec3(0.0f));
        const float theta = glm::radians(60.0f);
        addSun(scene, {std::sin(theta), -std::cos(theta), 0.0f}, 1000.0f);
        addOrthographicCamera(scene, {0.0f, 2.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 1.0f);
        const auto out = render(scene, 16, 4, 3, 0);
        const double expected = 0.8 / M_PI * 1000.0 / 683.0 * std::cos(theta);
        const ChannelStats s = channelStats(out.radiance, 0);
        QVERIFY2(std::abs(s.minimum - expected) < 0.01 * expected && std::abs(s.maximum - expected) < 0.01 * expected,
                 qPrintable(QString("[%1, %2] vs %3").arg(s.minimum).arg(s.maximum).arg(expected)));
    }

    // The same plane in raw light units: 2 W/m^2 at normal incidence gives 0.8 / pi * 2.
    void rawLightUnitsUseIntensityAsIs() {
        Scene scene;
        scene.settings.lightUnits = LightUnits::Raw;
        const MaterialId ground = scene.materials.add(lambert(glm::vec3(0.8f)));
        addShape(scene, ShapeKind::GroundPlane, ground, glm::vec3(0.0f));
        addSun(scene, {0.0f, -1.0f, 0.0f}, 2.0f);
        addOrthographicCamera(scene, {0.0f, 2.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 1.0f);
        const auto out = render(scene, 8, 1, 0, 0);
        const double expected = 0.8 / M_PI * 2.0;
        QVERIFY(std::abs(channelStats(out.radiance, 1).mean - expected) < 0.001 * expected);
    }
};

QTEST_APPLESS_MAIN(TestRenderPhysics)
#include "test_render_physics.moc"
