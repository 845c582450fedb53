// The last bounce (docs/PERFORMANCE.md, "The last bounce's BSDF ray"): where light sampling reaches
// every emitter, a path ends at its last vertex's light samples instead of tracing one more ray for
// MIS. These scenes are the cases where that would lose light, each with a closed-form answer at 0
// bounces (the first vertex is the last): emitters only rays find (an emissive ground plane, an
// emissive-textured one, a background colour) and a mirror, whose delta lobe light samples never
// meet. Ended there, each would render black. The same holds after a ground is made emissive in
// place, which must reach the path tracer's choice without a full upload.
#include "render_scene.h"
#include "scene_builder.h"
#include "test_render_textures_scenes.h"

#include "renderer/frame_renderer.h"
#include "renderer/gl/headless_context.h"
#include "renderer/offline_render.h"
#include "scene/history/asset_commands.h"

#include <QTest>

#include <cmath>
#include <memory>

using namespace glint;
using namespace glint::test;

namespace {

constexpr int kSize = 16;
constexpr float kAlbedo = 0.5f;
const glm::vec3 kEmission(2.0f);
const glm::quat kFacingDown = glm::angleAxis(glm::pi<float>(), glm::vec3(1.0f, 0.0f, 0.0f));

// 4x4 white texels: an emissive texture that leaves the factor as it is.
Texels white() {
    Texels t{4, 4, {}};
    for (int i = 0; i < t.width * t.height; ++i) t.rgba.insert(t.rgba.end(), {255, 255, 255, 255});
    return t;
}

// A grey quad facing down 1 m over an infinite emissive ground plane (its emission textured with
// white texels, or not), seen from below through a 2 cm orthographic window: its whole hemisphere
// is the ground, so it reflects albedo x emission.
Scene quadOverEmissiveGround(bool textured, glm::vec3 emission = kEmission) {
    Scene scene;
    scene.settings.environment.color = glm::vec3(0.0f);
    Material ground = lambert(glm::vec3(0.0f), emission);
    if (textured) ground.emissiveTexture = ref(addTexture(scene, white(), sampler(Filter::Nearest)));
    addShape(scene, ShapeKind::GroundPlane, scene.materials.add(std::move(ground)), glm::vec3(0.0f));
    addShape(scene, ShapeKind::Quad, scene.materials.add(lambert(glm::vec3(kAlbedo))), {0.0f, 1.0f, 0.0f}, 0.5f,
             glm::vec3(4.0f), kFacingDown);
    addOrthographicCamera(scene, {0.0f, 0.5f, 0.0f}, {0.0f, 1.0f, 0.0f}, 0.01f);
    return scene;
}

// A grey quad facing up under a sky of the emission's colour, seen from above.
Scene quadUnderSky() {
    Scene scene;
    scene.settings.environment.color = kEmission;
    addShape(scene, ShapeKind::Quad, scene.materials.add(lambert(glm::vec3(kAlbedo))), glm::vec3(0.0f), 0.5f, glm::vec3(4.0f));
    addOrthographicCamera(scene, {0.0f, 0.5f, 0.0f}, {0.0f, -1.0f, 0.0f}, 0.01f);
    return scene;
}

} // namespace

class TestRenderLastBounce : public QObject {
    Q_OBJECT
    std::unique_ptr<renderer::OfflineRenderer> renderer_;

    // The mean of channel 1 and its largest deviation from `expected`, relative.
    static std::pair<double, double> meanAndWorst(const renderer::RenderOutput& out, double expected) {
        double sum = 0.0, worst = 0.0;
        const std::size_t pixels = out.radiance.size() / 4;
        for (std::size_t i = 0; i < pixels; ++i) {
            sum += out.radiance[i * 4 + 1];
            worst = std::max(worst, std::abs(out.radiance[i * 4 + 1] / expected - 1.0));
        }
        return {sum / double(pixels) / expected - 1.0, worst};
    }

    renderer::RenderOutput render(const Scene& scene, int spp) {
        renderer::RenderRequest request = stillRequest(kSize, spp, 1, 0);
        request.tonemapper = Tonemapper::None;
        return renderer_->render(scene, request);
    }

private slots:
    void initTestCase() { renderer_ = std::make_unique<renderer::OfflineRenderer>(); }
    void cleanupTestCase() { renderer_.reset(); }

    // 16x16, 16 spp, 0 bounces: the quad reflects albedo x emission (1.0). Cosine-weighted BSDF
    // samples of a uniform hemisphere all carry that value, so every pixel is within 0.5 %.
    void emittersOnlyRaysFindStillLightTheLastVertex_data() {
        QTest::addColumn<int>("which");
        QTest::newRow("emissive ground plane") << 0;
        QTest::newRow("emissive-textured ground plane") << 1;
        QTest::newRow("background colour") << 2;
    }
    void emittersOnlyRaysFindStillLightTheLastVertex() {
        QFETCH(int, which);
        const Scene scene = which == 2 ? quadUnderSky() : quadOverEmissiveGround(which == 1);
        const double expected = kAlbedo * kEmission.y;
        const auto [mean, worst] = meanAndWorst(render(scene, 16), expected);
        qInfo("mean %+.4f %%, worst pixel %.4f %% (closed form %.3f)", 100.0 * mean, 100.0 * worst, expected);
        QVERIFY2(std::abs(mean) < 0.005 && worst < 0.005, qPrintable(QString("mean %1, worst %2 (relative)").arg(mean).arg(worst)));
    }

    // 16x16, 4 spp, 0 bounces: a mirror (white metal, roughness 0) seen straight down reflects an
    // emissive quad 1 m over it: the emission itself, within 0.5 %. Light samples cannot meet a
    // delta lobe, so the BSDF-sampled ray is what finds it even where every emitter is light-sampled.
    void aMirrorStillReflectsTheLightAtTheLastVertex() {
        Scene scene;
        scene.settings.environment.color = glm::vec3(0.0f);
        addShape(scene, ShapeKind::Quad, scene.materials.add(mirror()), glm::vec3(0.0f), 0.5f, glm::vec3(4.0f));
        addShape(scene, ShapeKind::Quad, scene.materials.add(lambert(glm::vec3(0.0f), kEmission)), {0.0f, 1.0f, 0.0f}, 0.5f,
                 glm::vec3(4.0f), kFacingDown);
        addOrthographicCamera(scene, {0.0f, 0.5f, 0.0f}, {0.0f, -1.0f, 0.0f}, 0.01f);
        const auto [mean, worst] = meanAndWorst(render(scene, 4), kEmission.y);
        qInfo("mean %+.4f %%, worst pixel %.4f %%", 100.0 * mean, 100.0 * worst);
        QVERIFY2(std::abs(mean) < 0.005 && worst < 0.005, qPrintable(QString("mean %1, worst %2 (relative)").arg(mean).arg(worst)));
    }

    // 16x16, 4 spp, 0 bounces: the ground of emittersOnlyRaysFindStillLightTheLastVertex starts dark
    // and is made emissive in place (FrameRenderer::applyChangesInPlace, GpuScene::updateMaterials):
    // the quad then reflects albedo x emission within 0.5 %, as after a full upload. Last: it makes
    // a context of its own current.
    void aGroundMadeEmissiveInPlaceLightsTheLastVertex() {
        renderer_.reset();
        gl::HeadlessContext context;
        Scene scene = quadOverEmissiveGround(false, glm::vec3(0.0f));
        renderer::FrameSettings settings;
        settings.spp = 4;
        settings.bounces = 0;
        settings.width = settings.height = kSize;
        settings.tonemapper = Tonemapper::None;
        renderer::FrameRenderer frames;
        frames.setSettings(settings);
        frames.setCamera(renderer::resolveCamera(scene, "", kSize, kSize));
        frames.setScene(scene);
        frames.renderFrame();

        const MaterialId ground = scene.at(scene.roots().front()).get<Shape>()->material;
        Material emissive = scene.materials.at(ground);
        emissive.emissiveFactor = kEmission;
        QVERIFY(frames.applyChangesInPlace(scene, SetMaterial(ground, emissive).apply(scene)));
        frames.renderFrame();
        renderer::RenderOutput out;
        out.radiance = frames.readImages().radiance;
        const double expected = kAlbedo * kEmission.y;
        const auto [mean, worst] = meanAndWorst(out, expected);
        qInfo("in place: mean %+.4f %%, worst pixel %.4f %%", 100.0 * mean, 100.0 * worst);
        QVERIFY2(std::abs(mean) < 0.005 && worst < 0.005, qPrintable(QString("mean %1, worst %2 (relative)").arg(mean).arg(worst)));
    }
};

QTEST_GUILESS_MAIN(TestRenderLastBounce)
#include "test_render_last_bounce.moc"
