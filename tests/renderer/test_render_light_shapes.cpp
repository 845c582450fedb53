// Lights with extent from Glint's light extension: point/spot lights with a radius (spheres of
// uniform radiance I / (pi r^2), sampled by the cone they subtend) and a sun with an angular
// diameter, whose disk camera rays see.
#include "image_stats.h"
#include "render_scene.h"
#include "scene_builder.h"

#include "renderer/offline_render.h"

#include <QTest>

#include <cmath>
#include <memory>

using namespace glint;
using namespace glint::test;

namespace {

constexpr double kPi = 3.14159265358979;

NodeId addPointLight(Scene& scene, glm::vec3 position, float candela, float radius) {
    Light light;
    light.type = LightType::Point;
    light.intensity = candela;
    light.radius = radius;
    return addNode(scene, "lamp", light, position);
}

renderer::RenderOutput render(renderer::OfflineRenderer& r, const Scene& scene, int size, int spp, std::uint32_t seed) {
    return test::renderScene(r, scene, size, spp, seed);
}

} // namespace

class TestRenderLightShapes : public QObject {
    Q_OBJECT
    std::unique_ptr<renderer::OfflineRenderer> renderer_;

    // Pixels of a 32x32, 16 spp top view of a white ground under a 683 cd lamp 1 m up at x = 0.6,
    // beside a square occluder 0.5 m up whose edge is at x = 0, whose visibility of the lamp (the
    // ratio to the same view without the occluder) is between 5 % and 95 %: the penumbra.
    int penumbraPixels(float radius) {
        const auto view = [&](bool occluded) {
            Scene scene;
            const MaterialId white = scene.materials.add(lambert(glm::vec3(1.0f)));
            addShape(scene, ShapeKind::GroundPlane, white, glm::vec3(0.0f));
            if (occluded) addShape(scene, ShapeKind::Quad, white, {-0.5f, 0.5f, 0.0f}, 0.5f, glm::vec3(1.0f, 1.0f, 4.0f));
            addPointLight(scene, {0.6f, 1.0f, 0.0f}, 683.0f, radius);
            addOrthographicCamera(scene, {0.0f, 0.4f, 0.0f}, {0.0f, -1.0f, 0.0f}, 0.4f);
            return render(*renderer_, scene, 32, 16, 21).radiance;
        };
        const auto shadowed = view(true);
        const auto open = view(false);
        int count = 0;
        for (std::size_t i = 0; i < open.size(); i += 4) {
            const double visible = shadowed[i + 1] / std::max(open[i + 1], 1e-9f);
            if (visible > 0.05 && visible < 0.95) ++count;
        }
        return count;
    }

private slots:
    void initTestCase() { renderer_ = std::make_unique<renderer::OfflineRenderer>(); }
    void cleanupTestCase() { renderer_.reset(); }

    // 16x16, 16 spp, seed 20. A sphere lamp (radius 0.2 m, 683 cd) 2 m above a white Lambert ground:
    // a sphere's irradiance on a facing plane is exactly I / d^2, so the pixels below show
    // 1/pi x 1/4 like a point lamp's (within 1 %).
    void sphereLampIrradianceMatchesPointLamp() {
        Scene scene;
        addShape(scene, ShapeKind::GroundPlane, scene.materials.add(lambert(glm::vec3(1.0f))), glm::vec3(0.0f));
        addPointLight(scene, {0.0f, 2.0f, 0.0f}, 683.0f, 0.2f);
        addOrthographicCamera(scene, {0.0f, 0.1f, 0.0f}, {0.0f, -1.0f, 0.0f}, 0.01f);
        const double mean = channelStats(render(*renderer_, scene, 16, 16, 20).radiance, 0).mean;
        const double expected = 1.0 / kPi / 4.0;
        QVERIFY2(std::abs(mean - expected) < 0.01 * expected, qPrintable(QString("%1 vs %2").arg(mean).arg(expected)));
    }

    // 32x32, 16 spp, seed 21. The occluder's shadow edge: a delta lamp leaves only the pixels the
    // edge crosses (box filter: one column) partly lit; a 0.3 m sphere lamp a penumbra > 4x as wide.
    void sphereLampSoftensShadows() {
        const int hard = penumbraPixels(0.0f);
        const int soft = penumbraPixels(0.3f);
        QVERIFY2(hard <= 2 * 32 && soft > 4 * std::max(hard, 1), qPrintable(QString("delta %1, sphere %2").arg(hard).arg(soft)));
    }

    // 8x8, 1 spp, seed 22. A 683 lux sun (irradiance 1) of angular diameter 0.1 rad is a disk of
    // radiance 1 / (2 pi (1 - cos 0.05)) = 127.35 that a camera looking at it sees (within 0.1 %);
    // a delta sun (no diameter) is not seen at all.
    void sunDiskIsSeenByCamera() {
        const double disk = 1.0 / (2.0 * kPi * (1.0 - std::cos(0.05)));
        const auto view = [&](float diameter) {
            Scene sky;
            addSun(sky, {0.0f, 0.0f, -1.0f}, 683.0f, diameter);
            addPerspectiveCamera(sky, glm::vec3(0.0f), {0.0f, 0.0f, 1.0f}, 0.02f);
            return channelStats(render(*renderer_, sky, 8, 1, 22).radiance, 0);
        };
        const ChannelStats direct = view(0.1f);
        QVERIFY2(std::abs(direct.minimum - disk) < 1e-3 * disk && std::abs(direct.maximum - disk) < 1e-3 * disk,
                 qPrintable(QString("direct %1 .. %2 vs %3").arg(direct.minimum).arg(direct.maximum).arg(disk)));
        QCOMPARE(view(0.0f).maximum, 0.0);
    }
};

QTEST_APPLESS_MAIN(TestRenderLightShapes)
#include "test_render_light_shapes.moc"
