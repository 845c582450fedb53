// Stress scenes must never give a NaN, an Inf or a negative pixel: degenerate shapes and singular
// transforms, grazing angles, coordinates near 1e5 (no acne, no leaks), environments with huge values.
#include "image_stats.h"
#include "render_scene.h"
#include "scene_builder.h"

#include "renderer/offline_render.h"

#include <OpenImageIO/imageio.h>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <memory>

using namespace glint;
using namespace glint::test;

namespace {

// Ground, a sphere resting on it, and a sun, all shifted by `origin`.
Scene sphereOnGround(glm::vec3 origin) {
    Scene scene;
    const MaterialId grey = scene.materials.add(lambert(glm::vec3(0.6f)));
    addShape(scene, ShapeKind::GroundPlane, grey, origin);
    addShape(scene, ShapeKind::Sphere, grey, origin + glm::vec3(0.0f, 0.5f, 0.0f));
    addSun(scene, {0.4f, -1.0f, -0.3f}, 1000.0f);
    addPerspectiveCamera(scene, origin + glm::vec3(0.0f, 1.0f, 3.0f), origin + glm::vec3(0.0f, 0.4f, 0.0f), 0.8f);
    return scene;
}

QString firstBadValue(const renderer::RenderOutput& out) {
    for (std::size_t i = 0; i < out.radiance.size(); ++i)
        if (!std::isfinite(out.radiance[i]) || out.radiance[i] < 0.0f) return QString("radiance[%1] = %2").arg(i).arg(out.radiance[i]);
    for (const auto* aov : {&out.albedo, &out.normal, &out.variance})
        for (std::size_t i = 0; i < aov->size(); ++i)
            if (!std::isfinite((*aov)[i])) return QString("AOV value %1 = %2").arg(i).arg((*aov)[i]);
    return {};
}

} // namespace

class TestRenderRobustness : public QObject {
    Q_OBJECT
    std::unique_ptr<renderer::OfflineRenderer> renderer_;

    renderer::RenderOutput render(const Scene& scene, int spp, std::uint32_t seed, std::filesystem::path env = {}) {
        renderer::RenderRequest request = test::stillRequest(32, spp, seed, 4);
        request.envFile = std::move(env);
        return renderer_->render(scene, request);
    }

private slots:
    void initTestCase() { renderer_ = std::make_unique<renderer::OfflineRenderer>(); }
    void cleanupTestCase() { renderer_.reset(); }

    // 32x32, 8 spp, seed 21: zero-sized shapes of every kind and a node scaled to 0 (a singular
    // transform whose inverse is not finite) in front of the camera.
    void degenerateShapesStayFinite() {
        Scene scene = sphereOnGround(glm::vec3(0.0f));
        const MaterialId glassy = scene.materials.add(glass(1.5f, 1.0f));
        addShape(scene, ShapeKind::Sphere, glassy, {0.0f, 0.5f, 1.0f}, 0.0f);
        addShape(scene, ShapeKind::Box, glassy, {0.2f, 0.5f, 1.0f}, 0.5f, glm::vec3(0.0f));
        addShape(scene, ShapeKind::Quad, glassy, {-0.2f, 0.5f, 1.0f}, 0.5f, glm::vec3(0.0f));
        addShape(scene, ShapeKind::Disk, glassy, {0.0f, 0.7f, 1.0f}, 0.0f);
        Shape flat;
        flat.kind = ShapeKind::Cylinder;
        flat.material = glassy;
        flat.radius = 0.0f;
        flat.height = 0.0f;
        addNode(scene, "flat cylinder", flat, {0.0f, 0.3f, 1.0f});
        Shape squashed;
        squashed.material = glassy;
        addNode(scene, "scaled to zero", squashed, {0.1f, 0.4f, 1.2f}, glm::quat(1.0f, 0.0f, 0.0f, 0.0f), glm::vec3(0.0f));
        const auto out = render(scene, 8, 21);
        QVERIFY2(firstBadValue(out).isEmpty(), qPrintable(firstBadValue(out)));
        QVERIFY(channelStats(out.radiance, 0).maximum > 0.0);
    }

    // 32x32, 16 spp, seed 22: the same sphere-on-ground scene at the origin and shifted by
    // (1e5, 1e5, -1e5). Self-intersection would darken the far copy (acne: about half the lit pixels)
    // or light its shadow (leaks): the mean radiance agrees within 2 % and the shadowed fraction of
    // pixels within 3 % of the image (floats near 1e5 are 8 mm apart, a tenth of a pixel here, so
    // pixels on the shadow's edge may flip).
    void coordinatesNear1e5MatchTheOrigin() {
        const auto near = render(sphereOnGround(glm::vec3(0.0f)), 16, 22);
        const auto far = render(sphereOnGround({1e5f, 1e5f, -1e5f}), 16, 22);
        QVERIFY2(firstBadValue(far).isEmpty(), qPrintable(firstBadValue(far)));
        const double nearMean = channelStats(near.radiance, 1).mean, farMean = channelStats(far.radiance, 1).mean;
        QVERIFY2(std::abs(farMean - nearMean) < 0.02 * nearMean, qPrintable(QString("%1 vs %2").arg(farMean).arg(nearMean)));
        const auto darkShare = [](const renderer::RenderOutput& o) {
            int dark = 0;
            for (std::size_t i = 1; i < o.radiance.size(); i += 4) dark += o.radiance[i] < 0.05f;
            return dark / 1024.0;
        };
        QVERIFY2(std::abs(darkShare(far) - darkShare(near)) < 0.03, qPrintable(QString("%1 vs %2").arg(darkShare(far)).arg(darkShare(near))));
    }

    // 32x32, 8 spp, seed 23: a camera 1e-4 m above the ground looking along it, a sun 0.01 degrees
    // above the horizon, a mirror ground: grazing everything.
    void grazingAnglesStayFinite() {
        Scene scene;
        const MaterialId chrome = scene.materials.add(mirror());
        const MaterialId grey = scene.materials.add(lambert(glm::vec3(0.5f)));
        addShape(scene, ShapeKind::GroundPlane, chrome, glm::vec3(0.0f));
        addShape(scene, ShapeKind::Box, grey, {0.0f, 0.5f, -5.0f});
        const float elevation = glm::radians(0.01f);
        addSun(scene, {std::cos(elevation), -std::sin(elevation), 0.0f}, 1000.0f);
        scene.settings.environment.color = glm::vec3(0.2f);
        addPerspectiveCamera(scene, {0.0f, 1e-4f, 0.0f}, {0.0f, 1e-4f, -1.0f}, 0.5f);
        const auto out = render(scene, 8, 23);
        QVERIFY2(firstBadValue(out).isEmpty(), qPrintable(firstBadValue(out)));
    }

    // 32x32, 8 spp, seed 24: a uniform sky of 1e30 and, separately, an 8x4 map with one texel of
    // 1e30 among ones (written to a temp dir): values stay finite and non-negative.
    void hugeEnvironmentValuesStayFinite() {
        Scene scene = sphereOnGround(glm::vec3(0.0f));
        scene.settings.environment.color = glm::vec3(1e30f);
        const auto uniform = render(scene, 8, 24);
        QVERIFY2(firstBadValue(uniform).isEmpty(), qPrintable(firstBadValue(uniform)));

        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const std::filesystem::path file = std::filesystem::path(dir.path().toStdString()) / "huge.hdr";
        std::vector<float> texels(8 * 4 * 3, 1.0f);
        texels[(1 * 8 + 3) * 3 + 0] = texels[(1 * 8 + 3) * 3 + 1] = texels[(1 * 8 + 3) * 3 + 2] = 1e30f;
        auto output = OIIO::ImageOutput::create(file.string());
        QVERIFY(output && output->open(file.string(), OIIO::ImageSpec(8, 4, 3, OIIO::TypeDesc::FLOAT)));
        QVERIFY(output->write_image(OIIO::TypeDesc::FLOAT, texels.data()));
        output->close();
        const auto mapped = render(sphereOnGround(glm::vec3(0.0f)), 8, 24, file);
        QVERIFY2(firstBadValue(mapped).isEmpty(), qPrintable(firstBadValue(mapped)));
    }
};

QTEST_APPLESS_MAIN(TestRenderRobustness)
#include "test_render_robustness.moc"
