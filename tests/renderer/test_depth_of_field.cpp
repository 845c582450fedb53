// Depth of field against the thin-lens model. A tiny emitting sphere on the optical axis, seen
// through a lens of radius R focused at distance f, images to a uniform disk whose radius on the
// plane of focus is R |z - f| / z (z: the point's distance); in pixels, over an image H pixels
// high with vertical field of view fov, that is R |z - f| / (z f tan(fov / 2)) x H / 2. The disk's
// radius is measured from the image's second moment (a uniform disk of radius r has mean squared
// distance r^2 / 2 from its centre; blurring the sphere's own in-focus disk of radius a adds a^2 / 2).
#include "render_scene.h"
#include "scene_builder.h"

#include <QTest>

#include <cmath>
#include <memory>

using namespace glint;
using namespace glint::test;

namespace {

constexpr int kSize = 128;
constexpr float kFov = 0.8f;
constexpr float kLensRadius = 0.2f;
constexpr float kFocus = 4.0f;

struct Blur {
    double radiusPx = 0.0;
    double centreX = 0.0, centreY = 0.0;
    double energy = 0.0;
};

// Intensity-weighted centre and sqrt(2 x mean squared distance) of channel 0.
Blur measureBlur(const std::vector<float>& radiance) {
    Blur b;
    double sx = 0.0, sy = 0.0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const double v = radiance[std::size_t(y * kSize + x) * 4];
            b.energy += v;
            sx += v * (x + 0.5);
            sy += v * (y + 0.5);
        }
    b.centreX = sx / b.energy;
    b.centreY = sy / b.energy;
    double s2 = 0.0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const double v = radiance[std::size_t(y * kSize + x) * 4];
            const double dx = x + 0.5 - b.centreX, dy = y + 0.5 - b.centreY;
            s2 += v * (dx * dx + dy * dy);
        }
    b.radiusPx = std::sqrt(2.0 * s2 / b.energy);
    return b;
}

constexpr float kAngularRadius = 0.005f; // of the sphere, seen from the lens: 0.76 px in focus

double pixelsPerRadian() { return 0.5 * kSize / std::tan(0.5 * kFov); }

// The blur disk convolved with the sphere's own disk, as the second moment sees it.
double thinLensRadiusPx(double z) {
    const double blur = kLensRadius * std::abs(z - kFocus) / (z * kFocus) * pixelsPerRadian();
    const double own = kAngularRadius * pixelsPerRadian();
    return std::sqrt(blur * blur + own * own);
}

Scene pointAt(float z) {
    Scene scene;
    const MaterialId glow = scene.materials.add(lambert(glm::vec3(0.0f), glm::vec3(1.0f)));
    addShape(scene, ShapeKind::Sphere, glow, glm::vec3(0.0f, 0.0f, -z), kAngularRadius * z);
    const NodeId cameraNode = addPerspectiveCamera(scene, glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f), kFov);
    Camera camera = *scene.at(cameraNode).get<Camera>();
    camera.lensRadius = kLensRadius;
    camera.focusDistance = kFocus;
    scene.setComponent(cameraNode, camera);
    return scene;
}

} // namespace

class TestDepthOfField : public QObject {
    Q_OBJECT
    std::unique_ptr<renderer::OfflineRenderer> renderer_;

    Blur render(float z) {
        renderer::RenderRequest request = stillRequest(kSize, 2048, 7, 0);
        request.tonemapper = Tonemapper::None;
        return measureBlur(renderer_->render(pointAt(z), request).radiance);
    }

private slots:
    void initTestCase() { renderer_ = std::make_unique<renderer::OfflineRenderer>(); }
    void cleanupTestCase() { renderer_.reset(); }

    // Nearer and farther than the focus: the disk's radius within 4 % of the thin-lens value (the
    // pixel filter and the sphere's own size add well under 1 %), centred on the axis.
    void circleOfConfusionFollowsTheThinLens_data() {
        QTest::addColumn<float>("z");
        QTest::newRow("near, 2 m") << 2.0f;
        QTest::newRow("far, 12 m") << 12.0f;
        QTest::newRow("nearer, 1.5 m") << 1.5f;
    }
    void circleOfConfusionFollowsTheThinLens() {
        QFETCH(float, z);
        const Blur blur = render(z);
        const double expected = thinLensRadiusPx(z);
        qInfo("z %.1f m: disk radius %.2f px, thin lens %.2f px", double(z), blur.radiusPx, expected);
        QVERIFY(blur.energy > 0.0);
        QVERIFY2(std::abs(blur.radiusPx - expected) < 0.04 * expected, qPrintable(QString::number(blur.radiusPx)));
        QVERIFY(std::abs(blur.centreX - 0.5 * kSize) < 0.25 && std::abs(blur.centreY - 0.5 * kSize) < 0.25);
    }

    // At the focus distance the sphere is as sharp as without a lens: its own disk (0.76 px) and
    // the pixel filter, well under the 5 px and more of the blurred cases.
    void aPointInFocusStaysSharp() {
        const Blur blur = render(kFocus);
        qInfo("in focus: radius %.2f px", blur.radiusPx);
        QVERIFY(blur.radiusPx < 1.5);
    }
};

QTEST_MAIN(TestDepthOfField)
#include "test_depth_of_field.moc"
