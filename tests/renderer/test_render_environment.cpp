// The environment map: orientation as docs/UNITS.md "Environment" says, rotation, and importance
// sampling with MIS giving the irradiance integral. The HDR is tests/data/env (see its LICENSES.md).
#include "image_stats.h"
#include "render_scene.h"
#include "scene_builder.h"

#include "renderer/gpu_scene/environment_image.h"
#include "renderer/offline_render.h"

#include <QTest>

#include <cmath>
#include <memory>

using namespace glint;
using namespace glint::test;

namespace {

const std::filesystem::path hdr = std::filesystem::path(GLINT_TEST_DATA_DIR) / "env" / "studio_small_03_1k.hdr";

// What GL_LINEAR with GL_REPEAT in u and GL_CLAMP_TO_EDGE in v returns at (u, v), green channel.
double bilinearGreen(const renderer::EnvironmentImage& image, double u, double v) {
    const double x = u * image.width - 0.5, y = v * image.height - 0.5;
    const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
    const double fx = x - x0, fy = y - y0;
    const auto at = [&](int px, int py) {
        px = ((px % image.width) + image.width) % image.width;
        py = std::clamp(py, 0, image.height - 1);
        return static_cast<double>(image.rgb[(static_cast<std::size_t>(py) * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(px)) * 3 + 1]);
    };
    return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) + fy * ((1 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
}

} // namespace

class TestRenderEnvironment : public QObject {
    Q_OBJECT
    std::unique_ptr<renderer::OfflineRenderer> renderer_;

    renderer::RenderOutput render(const Scene& scene, int size, int spp, std::uint32_t seed, int bounces) {
        renderer::RenderRequest request = test::stillRequest(size, spp, seed, bounces);
        request.envFile = hdr;
        return renderer_->render(scene, request);
    }

private slots:
    void initTestCase() { renderer_ = std::make_unique<renderer::OfflineRenderer>(); }
    void cleanupTestCase() { renderer_.reset(); }

    // 4x4, 1 spp, seed 0, a 0.001 rad field of view: each view direction d must show the map at
    // u = 0.5 + atan2(z, x) / 2pi, v = acos(y) / pi (and, rotated by 90 degrees about +Y, at the
    // direction turned back by -90 degrees). Tolerance 1 % of the bilinear value.
    void orientationFollowsTheContract_data() {
        QTest::addColumn<float>("x");
        QTest::addColumn<float>("y");
        QTest::addColumn<float>("z");
        QTest::addColumn<float>("rotation");
        QTest::newRow("+X is the centre") << 1.0f << 0.0f << 0.0f << 0.0f;
        QTest::newRow("-Z is u = 0.25") << 0.0f << 0.0f << -1.0f << 0.0f;
        QTest::newRow("+Z is u = 0.75") << 0.0f << 0.0f << 1.0f << 0.0f;
        QTest::newRow("up 60 degrees") << 0.5f << 0.866f << 0.0f << 0.0f;
        QTest::newRow("rotated 90: -Z shows +X") << 0.0f << 0.0f << -1.0f << 90.0f;
    }
    void orientationFollowsTheContract() {
        QFETCH(float, x);
        QFETCH(float, y);
        QFETCH(float, z);
        QFETCH(float, rotation);
        Scene scene;
        scene.settings.environment.rotationDegrees = rotation;
        addPerspectiveCamera(scene, glm::vec3(0.0f), glm::vec3(x, y, z), 0.001f);
        const auto out = render(scene, 4, 1, 0, 0);
        const auto image = renderer::loadEnvironmentImage(hdr);
        const double angle = glm::radians(-rotation); // the map turns by +rotation: look up at -rotation
        const glm::dvec3 d = glm::normalize(glm::dvec3(std::cos(angle) * x + std::sin(angle) * z, y, -std::sin(angle) * x + std::cos(angle) * z));
        const double expected = bilinearGreen(image, 0.5 + std::atan2(d.z, d.x) / (2 * M_PI), std::acos(d.y) / M_PI);
        const double actual = channelStats(out.radiance, 1).mean;
        QVERIFY2(std::abs(actual - expected) < 0.01 * expected, qPrintable(QString("%1 vs %2").arg(actual).arg(expected)));
    }

    // 16x16, 256 spp, seed 7, 0 bounces. An orthographic camera looks down on a white Lambert ground
    // plane lit by the map alone: L = 1/pi * integral over the upper hemisphere of L_env cos(theta),
    // summed on the CPU over the map's texels (piecewise constant). Mean within 2 %.
    void lambertPlaneIntegratesTheMap() {
        Scene scene;
        const MaterialId white = scene.materials.add(lambert(glm::vec3(1.0f)));
        addShape(scene, ShapeKind::GroundPlane, white, glm::vec3(0.0f));
        addOrthographicCamera(scene, {0.0f, 1.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 1.0f);
        const auto out = render(scene, 16, 256, 7, 0);
        const auto image = renderer::loadEnvironmentImage(hdr);
        double irradiance = 0.0;
        for (int row = 0; row < image.height / 2; ++row) {
            const double theta = (row + 0.5) * M_PI / image.height;
            const double solidAngle = (2 * M_PI / image.width) * (M_PI / image.height) * std::sin(theta);
            for (int column = 0; column < image.width; ++column)
                irradiance += image.rgb[(static_cast<std::size_t>(row) * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(column)) * 3 + 1] *
                              std::cos(theta) * solidAngle;
        }
        const double expected = irradiance / M_PI;
        const double actual = channelStats(out.radiance, 1).mean;
        QVERIFY2(std::abs(actual - expected) < 0.02 * expected, qPrintable(QString("%1 vs %2").arg(actual).arg(expected)));
    }
};

QTEST_APPLESS_MAIN(TestRenderEnvironment)
#include "test_render_environment.moc"
