// Known-answer renders: white furnaces, a Lambert plane under the sun, a mirror and a glass slab.
// Each test states its size, spp, seed and tolerance. Scenes are built in code.
#include "image_stats.h"
#include "render_scene.h"
#include "scene_builder.h"

#include "renderer/offline_render.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <memory>

using namespace glint;
using namespace glint::test;

class TestRenderPhysics : public QObject {
    Q_OBJECT
    std::unique_ptr<renderer::OfflineRenderer> renderer_;

    renderer::RenderOutput render(const Scene& scene, int size, int spp, std::uint32_t seed, int bounces) {
        renderer::RenderRequest request = test::stillRequest(size, spp, seed, bounces);
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

    // 32x32, 1024 spp, seed 1, 64 bounces (Russian roulette decides). Walls of albedo 0.5 emitting 0.5
    // around a white Lambert sphere: radiance is 1 everywhere (L = 0.5 + 0.5 L). Image mean within
    // 0.5 % of 1; every pixel within 4 sigma of 1, sigma the standard error sqrt(variance / spp).
    void whiteFurnaceIsOne() {
        const int spp = 1024;
        const auto out = render(furnace(1.0f, 0.5f, 0.5f), 32, spp, 1, 64);
        for (int c = 0; c < 3; ++c) {
            const ChannelStats s = channelStats(out.radiance, c);
            QVERIFY2(std::abs(s.mean - 1.0) < 0.005, qPrintable(QString("channel %1 mean %2").arg(c).arg(s.mean)));
        }
        // Every pixel has the same expected distribution, so its standard error is pooled over the
        // image (a pixel's own variance estimate is too small exactly when its value is low).
        double pooledVariance = 0.0;
        for (const float v : out.variance) pooledVariance += v;
        const double sigma = std::sqrt(pooledVariance / static_cast<double>(out.variance.size()) / spp);
        for (std::size_t i = 0; i < out.variance.size(); ++i) {
            const double value = out.radiance[i / 3 * 4 + i % 3];
            QVERIFY2(std::abs(value - 1.0) <= 4.0 * sigma, qPrintable(QString("pixel %1: %2, sigma %3").arg(i / 3).arg(value).arg(sigma)));
        }
    }

    // 32x32, 256 spp, seed 2, 4 bounces. Black walls emitting 1 around a sphere of albedo 0.5: the
    // sphere shows 0.5, the walls 1. The wall is light-sampled (by area, from inside) and found by
    // BSDF rays, weighted by MIS, so sphere pixels are noisy (not exact as under BSDF sampling
    // alone). By symmetry every sphere pixel (the centre 16x16) has the same distribution: its
    // standard error sigma is pooled over them. Their mean within 4 sigma / 16 of 0.5 (a bound
    // itself under 0.5 %), each pixel within 4.5 sigma; a wall pixel is exactly 1 (camera rays see emission whole).
    void halfAlbedoFurnaceIsHalf() {
        const int spp = 256;
        const auto out = render(furnace(0.5f, 0.0f, 1.0f), 32, spp, 2, 4);
        double sum = 0.0, pooledVariance = 0.0;
        for (int y = 8; y < 24; ++y) {
            for (int x = 8; x < 24; ++x) {
                sum += pixel(out.radiance, 32, x, y, 1);
                pooledVariance += out.variance[std::size_t(y * 32 + x) * 3 + 1];
            }
        }
        const double sigma = std::sqrt(pooledVariance / 256.0 / spp);
        const double mean = sum / 256.0;
        QVERIFY2(4.0 * sigma / 16.0 < 0.0025, qPrintable(QString("sigma %1: too noisy to test").arg(sigma)));
        QVERIFY2(std::abs(mean - 0.5) < 4.0 * sigma / 16.0, qPrintable(QString("mean %1, sigma %2").arg(mean).arg(sigma)));
        for (int y = 8; y < 24; ++y)
            for (int x = 8; x < 24; ++x)
                QVERIFY2(std::abs(pixel(out.radiance, 32, x, y, 1) - 0.5f) < 4.5 * sigma,
                         qPrintable(QString("pixel %1,%2 = %3, sigma %4").arg(x).arg(y).arg(pixel(out.radiance, 32, x, y, 1)).arg(sigma)));
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
    // 32x32, 4 spp, seed 4, 0 bounces. An orthographic camera looks down (-Y) on a mirror tilted 45
    // degrees about Z (the plane y = x), which sends every ray along -X to an emitter spanning
    // y in [-1, 1], z in [-0.5, 0.5] at x = -4. The lit region of the image is x in [-1, 1] and z in
    // [-0.5, 0.5], exactly pixels 8..23 by rows 12..19 (4 m wide view, 1/8 m per pixel): there the
    // radiance is the emission (2), elsewhere 0. Tolerance 1e-5.
    void mirrorReflectsOntoKnownPixels() {
        Scene scene;
        const MaterialId mirrorMaterial = scene.materials.add(mirror());
        const MaterialId light = scene.materials.add(lambert(glm::vec3(0.0f), glm::vec3(2.0f)));
        const glm::quat tilt = glm::angleAxis(glm::radians(45.0f), glm::vec3(0.0f, 0.0f, 1.0f));
        const glm::quat upright = glm::angleAxis(glm::radians(90.0f), glm::vec3(0.0f, 0.0f, 1.0f));
        addShape(scene, ShapeKind::Quad, mirrorMaterial, glm::vec3(0.0f), 0.5f, {6.0f, 1.0f, 4.0f}, tilt);
        addShape(scene, ShapeKind::Quad, light, {-4.0f, 0.0f, 0.0f}, 0.5f, {2.0f, 1.0f, 1.0f}, upright);
        addOrthographicCamera(scene, {0.0f, 5.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 2.0f);
        const auto out = render(scene, 32, 4, 4, 0);
        for (int y = 0; y < 32; ++y) {
            for (int x = 0; x < 32; ++x) {
                const bool lit = x >= 8 && x < 24 && y >= 12 && y < 20;
                QVERIFY2(std::abs(pixel(out.radiance, 32, x, y, 0) - (lit ? 2.0f : 0.0f)) < 1e-5f,
                         qPrintable(QString("pixel %1,%2 = %3").arg(x).arg(y).arg(pixel(out.radiance, 32, x, y, 0))));
            }
        }
    }

    // 32x32, 256 spp, seed 5, 8 bounces. An orthographic camera looks 45 degrees down (+X, -Y)
    // through a glass slab (IOR 1.5, 1 m thick, a refracting solid) at an emitter covering x >= 0
    // on the ground. Refraction shifts the image of the emitter's edge by h (tan 45 - tan theta_t)
    // = 0.4655 m, so the edge falls 36.6 % of the way into row 13 (rows are 0.125 m of image height,
    // ground x = sqrt(2) v). Fully lit rows carry the slab's transmittance (1 - F)^2 / (1 - F^2)
    // (internal reflections included) within 2 %; row 13's share of it within 0.03 of 0.366.
    void glassSlabShiftsAndAttenuates() {
        Scene scene;
        const MaterialId slab = scene.materials.add(glass(1.5f, 1.0f));
        const MaterialId light = scene.materials.add(lambert(glm::vec3(0.0f), glm::vec3(1.0f)));
        addShape(scene, ShapeKind::Box, slab, {0.0f, 1.0f, 0.0f}, 0.5f, {20.0f, 1.0f, 20.0f});
        addShape(scene, ShapeKind::Quad, light, {5.0f, 0.0f, 0.0f}, 0.5f, {10.0f, 1.0f, 20.0f});
        addOrthographicCamera(scene, {-3.0f, 3.0f, 0.0f}, {1.0f, -1.0f, 0.0f}, 2.0f);
        const auto out = render(scene, 32, 256, 5, 8);

        const double cosI = std::sqrt(0.5), cosT = std::sqrt(1.0 - 0.5 / (1.5 * 1.5));
        const double rs = (cosI - 1.5 * cosT) / (cosI + 1.5 * cosT), rp = (1.5 * cosI - cosT) / (1.5 * cosI + cosT);
        const double fresnel = 0.5 * (rs * rs + rp * rp);
        const double transmittance = (1.0 - fresnel) * (1.0 - fresnel) / (1.0 - fresnel * fresnel);
        const double shift = 1.0 * (1.0 - std::sqrt(1.0 - cosT * cosT) / cosT);
        const double edgeV = shift / std::sqrt(2.0);
        const double litShareOfRow13 = (2.0 - 0.125 * 13 - edgeV) / 0.125;
        const auto rowMean = [&](int y) {
            double sum = 0.0;
            for (int x = 0; x < 32; ++x) sum += pixel(out.radiance, 32, x, y, 1);
            return sum / 32.0;
        };
        for (int y = 0; y < 13; ++y)
            QVERIFY2(std::abs(rowMean(y) - transmittance) < 0.02 * transmittance,
                     qPrintable(QString("row %1: %2 vs %3").arg(y).arg(rowMean(y)).arg(transmittance)));
        QVERIFY2(std::abs(rowMean(13) / transmittance - litShareOfRow13) < 0.03,
                 qPrintable(QString("row 13 share %1 vs %2").arg(rowMean(13) / transmittance).arg(litShareOfRow13)));
        QVERIFY2(rowMean(15) < 0.01 * transmittance, qPrintable(QString("row 15: %1").arg(rowMean(15))));
    }

    // 16x16, 16 spp, seed 6, 16 bounces. A camera inside a glass block (IOR 1.5) looks up at its top
    // face, above which an emitter of radiance 1 hangs. At 30 degrees from the normal (below the
    // critical angle, 41.8) the emitter shows through with (1 - F) n^2 (radiance grows by n^2 inside a
    // denser medium); at 60 degrees total internal reflection traps every path inside: exactly 0.
    void totalInternalReflection() {
        const auto renderAt = [&](float degrees) {
            Scene scene;
            const MaterialId block = scene.materials.add(glass(1.5f, 1.0f));
            const MaterialId light = scene.materials.add(lambert(glm::vec3(0.0f), glm::vec3(1.0f)));
            addShape(scene, ShapeKind::Box, block, glm::vec3(0.0f), 0.5f, glm::vec3(100.0f, 2.0f, 100.0f));
            addShape(scene, ShapeKind::Quad, light, {0.0f, 1.5f, 0.0f}, 0.5f, glm::vec3(100.0f, 1.0f, 100.0f));
            const float a = glm::radians(degrees);
            addOrthographicCamera(scene, glm::vec3(0.0f), {std::sin(a), std::cos(a), 0.0f}, 0.01f);
            return render(scene, 16, 16, 6, 16);
        };
        const double cosI = std::cos(glm::radians(30.0)), eta = 1.0 / 1.5;
        const double cosT = std::sqrt(1.0 - (1.0 - cosI * cosI) / (eta * eta));
        const double rs = (cosI - eta * cosT) / (cosI + eta * cosT), rp = (eta * cosI - cosT) / (eta * cosI + cosT);
        const double expected = (1.0 - 0.5 * (rs * rs + rp * rp)) * 1.5 * 1.5;
        const ChannelStats below = channelStats(renderAt(30.0f).radiance, 0);
        QVERIFY2(std::abs(below.mean - expected) < 0.03 * expected, qPrintable(QString("%1 vs %2").arg(below.mean).arg(expected)));
        QCOMPARE(channelStats(renderAt(60.0f).radiance, 0).maximum, 0.0);
    }
    // 3x3 pixels, 1 spp, seed 8, 0 bounces. An orthographic camera (1 mm across) looks straight down
    // at a white Lambert ground at x = -1, 0, +1 m; a light 2 m above x = 0 shines down. A point light
    // of I cd gives L = 1/pi * I/683 / d^2 * cos; a spot light (inner 10, outer 40 degrees) adds the
    // KHR_lights_punctual smooth falloff, ((cos a - cos outer) / (cos inner - cos outer))^2 clamped.
    // Tolerance 0.1 %.
    void pointAndSpotLightsFollowTheInverseSquareLaw_data() {
        QTest::addColumn<int>("type");
        QTest::newRow("point") << int(LightType::Point);
        QTest::newRow("spot") << int(LightType::Spot);
    }
    void pointAndSpotLightsFollowTheInverseSquareLaw() {
        QFETCH(int, type);
        const float inner = glm::radians(10.0f), outer = glm::radians(40.0f);
        for (float x : {-1.0f, 0.0f, 1.0f}) {
            Scene scene;
            const MaterialId white = scene.materials.add(lambert(glm::vec3(1.0f)));
            addShape(scene, ShapeKind::GroundPlane, white, glm::vec3(0.0f));
            Light light;
            light.type = static_cast<LightType>(type);
            light.intensity = 500.0f;
            light.innerConeAngle = inner;
            light.outerConeAngle = outer;
            addNode(scene, "light", light, {0.0f, 2.0f, 0.0f}, lookRotation({0.0f, -1.0f, 0.0f}, {0.0f, 0.0f, -1.0f}));
            addOrthographicCamera(scene, {x, 1.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 0.0005f);
            const auto out = render(scene, 3, 1, 8, 0);
            const double d2 = x * x + 4.0, cosine = 2.0 / std::sqrt(d2);
            double falloff = 1.0;
            if (light.type == LightType::Spot) {
                const double t = std::clamp((cosine - std::cos(outer)) / (std::cos(inner) - std::cos(outer)), 0.0, 1.0);
                falloff = t * t;
            }
            const double expected = 1.0 / M_PI * 500.0 / 683.0 / d2 * cosine * falloff;
            const double actual = channelStats(out.radiance, 0).mean;
            QVERIFY2(std::abs(actual - expected) <= 1e-3 * expected,
                     qPrintable(QString("x %1: %2 vs %3").arg(x).arg(actual).arg(expected)));
        }
    }
};

QTEST_APPLESS_MAIN(TestRenderPhysics)
#include "test_render_physics.moc"
