// Motion blur: a wide emitting quad slides along +X at 1 m/s (node keys, linear), seen from above
// through an orthographic camera 1 m wide. With the shutter open from t = 0.25 to 0.75 s its left
// edge sweeps from x = 0.25 to 0.75 m, so across the image the radiance ramps linearly from 0 to 1
// over those 0.5 m (32 of 64 pixels): the fraction of the shutter time each point is covered. The
// samples' instants are stratified over the shutter, so at 64 spp the ramp is exact to 1/64.
#include "render_scene.h"
#include "scene_builder.h"

#include "scene/anim/node_keys.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <memory>

using namespace glint;
using namespace glint::test;

namespace {

constexpr int kSize = 64;

Scene slidingQuad() {
    Scene scene;
    const MaterialId glow = scene.materials.add(lambert(glm::vec3(0.0f), glm::vec3(1.0f)));
    // 4 m wide: at x = 2 + t its left edge is at x = t.
    const NodeId quad = addShape(scene, ShapeKind::Quad, glow, glm::vec3(2.0f, 0.0f, 0.0f), 0.5f, glm::vec3(4.0f, 1.0f, 4.0f));
    Transform at = scene.at(quad).local;
    Animation slide = withNodeKey({}, quad, 0.0, at, Interpolation::Linear);
    at.translation.x = 3.0f;
    slide = withNodeKey(slide, quad, 1.0, at, Interpolation::Linear);
    scene.animations.add(slide);
    addOrthographicCamera(scene, {0.5f, 1.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 0.5f);
    return scene;
}

// The mean radiance of pixel column x over the middle rows.
double column(const std::vector<float>& radiance, int x) {
    double sum = 0.0;
    for (int y = kSize / 4; y < 3 * kSize / 4; ++y) sum += radiance[std::size_t(y * kSize + x) * 4 + 1];
    return sum / (kSize / 2);
}

} // namespace

class TestMotionBlur : public QObject {
    Q_OBJECT
    std::unique_ptr<renderer::OfflineRenderer> renderer_;

    std::vector<float> render(double shutterSeconds) {
        renderer::RenderRequest request = stillRequest(kSize, 64, 5, 0);
        request.tonemapper = Tonemapper::None;
        request.time = 0.5;
        request.shutterSeconds = shutterSeconds;
        return renderer_->render(slidingQuad(), request).radiance;
    }

private slots:
    void initTestCase() { renderer_ = std::make_unique<renderer::OfflineRenderer>(); }
    void cleanupTestCase() { renderer_.reset(); }

    // Each column's value against the ramp (x - 0.25) / 0.5 clamped to [0, 1], x the column's centre
    // in metres (the image is mirrored or not: the ramp rises towards the quad, +X, either way it is
    // checked against the side the sharp image says the quad is on). Within 0.03 everywhere.
    void aMovingEdgeBlursToALinearRamp() {
        const std::vector<float> sharp = render(0.0);
        const std::vector<float> blurred = render(0.5);
        const bool quadOnTheRight = column(sharp, kSize - 1) > 0.5;
        QVERIFY(quadOnTheRight != (column(sharp, 0) > 0.5)); // one edge in view
        double worst = 0.0;
        for (int x = 0; x < kSize; ++x) {
            const double metres = (quadOnTheRight ? x : kSize - 1 - x) + 0.5;
            const double expected = std::clamp((metres / kSize - 0.25) / 0.5, 0.0, 1.0);
            const double actual = column(blurred, x);
            worst = std::max(worst, std::abs(actual - expected));
            QVERIFY2(std::abs(actual - expected) < 0.03, qPrintable(QString("column %1: %2, ramp %3").arg(x).arg(actual).arg(expected)));
        }
        qInfo("largest difference from the ramp: %.4f", worst);
        // Without the shutter the edge is sharp at x = 0.5 m: columns a pixel away are 0 and 1.
        const int edge = kSize / 2;
        QVERIFY(std::abs(column(sharp, quadOnTheRight ? edge + 1 : edge - 2) - 1.0) < 1e-3);
        QVERIFY(column(sharp, quadOnTheRight ? edge - 2 : edge + 1) < 1e-3);
    }

    // A scene where nothing moves renders the same pixels with the shutter open as without.
    void aStillSceneIsUnchangedByTheShutter() {
        Scene still = slidingQuad();
        still.animations = {};
        renderer::RenderRequest request = stillRequest(kSize, 8, 5, 0);
        request.time = 0.5;
        const std::vector<float> a = renderer_->render(still, request).radiance;
        request.shutterSeconds = 0.5;
        QVERIFY(renderer_->render(still, request).radiance == a);
    }
};

QTEST_MAIN(TestMotionBlur)
#include "test_motion_blur.moc"
