// Bloom (renderer/passes/bloom_pass.h) on a small bright lamp over black, 64x64, Accumulate 4 spp,
// seed 0: strength 0 changes nothing (bit for bit); bloom spreads light without adding any (the
// bloomed radiance sums to the unbloomed within 0.5 %, the lamp sitting well inside the image); it
// lights pixels beside the lamp that were black; a wider radius reaches further; the EXR's radiance
// stays unbloomed unless asked (bloomLinear) while the 8-bit image shows the glare.
#include "renderer/frame_renderer.h"
#include "renderer/gl/headless_context.h"
#include "scene_builder.h"

#include <QtTest>

#include <numeric>

using namespace glint;
using namespace glint::test;

namespace {

constexpr int kSize = 64;

Scene lampScene() {
    Scene scene;
    const MaterialId lamp = scene.materials.add(lambert(glm::vec3(0.0f), glm::vec3(20.0f)));
    addShape(scene, ShapeKind::Sphere, lamp, glm::vec3(0.0f), 0.08f);
    addOrthographicCamera(scene, {0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, -1.0f}, 1.0f);
    return scene;
}

double sum(const std::vector<float>& rgba) {
    double total = 0.0;
    for (std::size_t i = 0; i < rgba.size(); i += 4) total += double(rgba[i]) + rgba[i + 1] + rgba[i + 2];
    return total;
}

// Radiance (green) at row `kSize / 2`, `dx` pixels right of the centre.
float beside(const std::vector<float>& rgba, int dx) {
    return rgba[4 * (std::size_t(kSize / 2) * kSize + std::size_t(kSize / 2 + dx)) + 1];
}

} // namespace

class TestBloom : public QObject {
    Q_OBJECT
    std::unique_ptr<gl::HeadlessContext> context_;
    std::unique_ptr<renderer::FrameRenderer> frames_;

    renderer::FrameImages render(const renderer::BloomSettings& bloom, bool linear) {
        renderer::FrameSettings s;
        s.configuration = renderer::Configuration::Accumulate;
        s.spp = 4;
        s.width = s.height = kSize;
        s.tonemapper = Tonemapper::None;
        s.bloom = bloom;
        s.bloomLinear = linear;
        frames_->setSettings(s);
        frames_->setScene(lampScene());
        frames_->renderFrame();
        return frames_->readImages();
    }

private slots:
    void initTestCase() {
        context_ = std::make_unique<gl::HeadlessContext>();
        frames_ = std::make_unique<renderer::FrameRenderer>();
    }
    void cleanupTestCase() {
        frames_.reset();
        context_.reset();
    }

    void strengthZeroChangesNothing() {
        const auto plain = render({}, false);
        const auto zero = render({0.0f, 0.3f}, true);
        QVERIFY(plain.radiance == zero.radiance);
        QVERIFY(plain.tonemapped == zero.tonemapped);
    }

    void spreadsLightWithoutAddingAny() {
        const auto plain = render({}, false);
        const auto bloomed = render({0.5f, 0.1f}, true);
        const double before = sum(plain.radiance), after = sum(bloomed.radiance);
        qInfo("radiance sum: %.3f without bloom, %.3f with (ratio %.5f)", before, after, after / before);
        QVERIFY(before > 10.0);
        QVERIFY2(std::abs(after / before - 1.0) < 0.005, qPrintable(QString::number(after / before)));
        QCOMPARE(beside(plain.radiance, 8), 0.0f); // black beside the lamp without bloom
        QVERIFY(beside(bloomed.radiance, 8) > 0.0f);
        QVERIFY(beside(bloomed.radiance, 0) < beside(plain.radiance, 0)); // the lamp gives what the glare gets
    }

    void widerRadiusReachesFurther() {
        const auto narrow = render({0.5f, 0.05f}, true);
        const auto wide = render({0.5f, 0.4f}, true);
        qInfo("12 px from the lamp: %.5f (radius 0.05), %.5f (radius 0.4)", beside(narrow.radiance, 12), beside(wide.radiance, 12));
        QVERIFY(beside(wide.radiance, 12) > 2.0f * beside(narrow.radiance, 12));
    }

    void exrStaysUnbloomedUnlessAsked() {
        const auto plain = render({}, false);
        const auto shown = render({0.5f, 0.1f}, false);
        QVERIFY(shown.radiance == plain.radiance);
        QVERIFY(shown.tonemapped != plain.tonemapped);
    }
};

QTEST_APPLESS_MAIN(TestBloom)
#include "test_bloom.moc"
