// Determinism (same seed: identical bits; another seed: different noise) and convergence (mean
// squared error against a reference falls like 1/spp, with no bias floor).
#include "image_stats.h"
#include "render_scene.h"
#include "scene_builder.h"

#include "renderer/offline_render.h"

#include <QTest>

#include <cmath>
#include <cstring>
#include <memory>

using namespace glint;
using namespace glint::test;

namespace {

// Ground, a diffuse, a mirror and a glass sphere under a soft sun and a uniform sky.
Scene studio(float sunDiameterDegrees = 2.0f) {
    Scene scene;
    scene.settings.environment.color = {0.3f, 0.4f, 0.5f};
    const MaterialId ground = scene.materials.add(lambert(glm::vec3(0.7f)));
    const MaterialId red = scene.materials.add(lambert({0.8f, 0.2f, 0.1f}));
    const MaterialId chrome = scene.materials.add(mirror());
    const MaterialId clear = scene.materials.add(glass(1.5f, 0.5f));
    addShape(scene, ShapeKind::GroundPlane, ground, glm::vec3(0.0f));
    addShape(scene, ShapeKind::Sphere, red, {-1.1f, 0.5f, 0.0f});
    addShape(scene, ShapeKind::Sphere, chrome, {0.0f, 0.5f, 0.0f});
    addShape(scene, ShapeKind::Sphere, clear, {1.1f, 0.5f, 0.0f});
    addSun(scene, {0.3f, -1.0f, -0.4f}, 2000.0f, glm::radians(sunDiameterDegrees));
    addPerspectiveCamera(scene, {0.0f, 1.5f, 4.0f}, {0.0f, 0.4f, 0.0f}, 0.7f);
    return scene;
}

double meanSquaredError(const std::vector<float>& a, const std::vector<float>& b) {
    double sum = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (i % 4 == 3) continue;
        const double d = static_cast<double>(a[i]) - b[i];
        sum += d * d;
        ++n;
    }
    return sum / static_cast<double>(n);
}

} // namespace

class TestRenderStatistics : public QObject {
    Q_OBJECT
    std::unique_ptr<renderer::OfflineRenderer> renderer_;

    std::vector<float> render(const Scene& scene, int size, int spp, std::uint32_t seed, bool independent = false) {
        renderer::RenderRequest request = test::stillRequest(size, spp, seed, 3);
        request.independentSampler = independent;
        return renderer_->render(scene, request).radiance;
    }

private slots:
    void initTestCase() { renderer_ = std::make_unique<renderer::OfflineRenderer>(); }
    void cleanupTestCase() { renderer_.reset(); }

    // 32x32, 4 spp, seeds 11 and 12, 3 bounces, both pixel samplers: the same seed gives identical
    // bytes; another seed changes more than half of the values.
    void sameSeedIsBitIdentical_data() {
        QTest::addColumn<bool>("independent");
        QTest::newRow("R2 jitter") << false;
        QTest::newRow("independent sampler") << true;
    }
    void sameSeedIsBitIdentical() {
        QFETCH(bool, independent);
        const Scene scene = studio();
        const auto first = render(scene, 32, 4, 11, independent);
        const auto second = render(scene, 32, 4, 11, independent);
        QCOMPARE(first.size(), second.size());
        QVERIFY(std::memcmp(first.data(), second.data(), first.size() * sizeof(float)) == 0);
        const auto other = render(scene, 32, 4, 12, independent);
        std::size_t differing = 0;
        for (std::size_t i = 0; i < first.size(); ++i) differing += first[i] != other[i];
        QVERIFY2(differing > first.size() / 2, qPrintable(QString("%1 of %2 differ").arg(differing).arg(first.size())));
    }

    // 16x16, 3 bounces: seed 1 at 4, 16, 64 and 256 spp against a reference of seed 1000 at 4096 spp
    // (16x the highest). The least-squares slope of log MSE over log spp must be <= -0.9.
    // The sun is 45 degrees wide here so that its images in the mirror and glass spheres and their
    // caustics on the ground are resolved at 4 spp: a 2-degree sun's image in the mirror sphere covers
    // 0.2 % of a pixel, so a render below ~500 spp almost never contains it and its error stays at the
    // missing highlight (measured: MSE 0.18 at 4, 16 and 64 spp). Over seeds 1..8 the slope is then
    // -1.01 .. -1.20.
    void errorFallsLikeOneOverSpp() {
        const Scene scene = studio(45.0f);
        const auto reference = render(scene, 16, 4096, 1000);
        std::vector<double> logSpp, logMse;
        for (int spp : {4, 16, 64, 256}) {
            logSpp.push_back(std::log(spp));
            logMse.push_back(std::log(meanSquaredError(render(scene, 16, spp, 1), reference)));
        }
        const double n = static_cast<double>(logSpp.size());
        double sx = 0, sy = 0, sxx = 0, sxy = 0;
        for (std::size_t i = 0; i < logSpp.size(); ++i) {
            sx += logSpp[i];
            sy += logMse[i];
            sxx += logSpp[i] * logSpp[i];
            sxy += logSpp[i] * logMse[i];
        }
        const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
        qInfo("MSE slope over 4..256 spp: %.3f", slope);
        QVERIFY2(slope <= -0.9, qPrintable(QString("slope %1").arg(slope)));
    }
};

QTEST_APPLESS_MAIN(TestRenderStatistics)
#include "test_render_statistics.moc"
