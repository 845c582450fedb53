// Diffuse and specular radiance apart (docs/DENOISING.md): the path tracer's split is a partition
// of the same samples (diffuse + specular = radiance, and the split leaves the radiance of the
// converging configurations untouched), SVGF filters the lobes apart on a glossy floor, and
// Baseline's ambient term brings an indirectly lit region closer to the reference while the
// converging configurations never compile it.
#include "reconstruction_fixture.h"

#include "renderer/gpu_scene/gpu_scene.h"

#include <QtTest>

#include <cstring>

using namespace glint;
using namespace glint::test;

namespace {

struct GlossyRoom {
    Scene scene;
    NodeId box, mirrorBall, metalBall;
};

// The reconstruction room with a polished floor (a white dielectric layer, roughness 0.1, over a
// grey base: sharp reflections on a rough diffuse base), a mirror ball, a brushed metal ball and a
// pure Lambert box (no specular lobe at all).
GlossyRoom makeGlossyRoom() {
    GlossyRoom room;
    Scene& s = room.scene;
    Material polished = lambert(glm::vec3(0.45f));
    polished.specularFactor = 1.0f;
    polished.roughnessFactor = 0.1f;
    Material brushed = mirror();
    brushed.baseColorFactor = glm::vec4(0.9f, 0.75f, 0.4f, 1.0f);
    brushed.roughnessFactor = 0.35f;
    const MaterialId floor = s.materials.add(polished);
    const MaterialId grey = s.materials.add(lambert(glm::vec3(0.6f)));
    const MaterialId red = s.materials.add(lambert({0.7f, 0.15f, 0.1f}));
    const MaterialId chrome = s.materials.add(mirror());
    const MaterialId gold = s.materials.add(brushed);
    addShape(s, ShapeKind::GroundPlane, floor, glm::vec3(0.0f));
    addShape(s, ShapeKind::Box, grey, {0.0f, 1.5f, -2.0f}, 0.5f, {6.0f, 3.0f, 0.2f});
    room.box = addShape(s, ShapeKind::Box, red, {-0.6f, 0.5f, -0.5f}, 0.5f, {0.6f, 1.0f, 0.6f});
    room.mirrorBall = addShape(s, ShapeKind::Sphere, chrome, {0.7f, 0.45f, -0.8f}, 0.45f);
    room.metalBall = addShape(s, ShapeKind::Sphere, gold, {0.1f, 0.3f, 0.6f}, 0.3f);
    addSun(s, {-0.4f, -1.0f, -0.5f}, 1500.0f);
    s.settings.activeCamera = addPerspectiveCamera(s, {0.0f, 1.2f, 4.0f}, {0.0f, 0.8f, 0.0f}, 0.9f);
    s.settings.environment.color = glm::vec3(0.15f, 0.18f, 0.25f);
    return room;
}

// One path-trace pass over a scene in the test's context, for reading the G-buffer's targets.
struct Tracer {
    gl::ProgramCache programs;
    renderer::PathTracePass pass{programs};
    renderer::MeshBvhCache meshes;
    std::unique_ptr<renderer::GpuScene> gpu;
    renderer::CameraSetup camera;
    gl::RenderTarget target = renderer::makeGBuffer(imageSize, imageSize);

    explicit Tracer(const Scene& scene)
        : gpu(std::make_unique<renderer::GpuScene>(scene, std::filesystem::path(), meshes)),
          camera(renderer::resolveCamera(scene, {}, imageSize, imageSize)) {}

    void trace(const renderer::PathTraceSettings& settings, std::uint32_t sample) {
        pass.render(*gpu, camera, settings, sample, target);
    }
    // Mean radiance (RGBA, GL rows) of samples 0..n-1.
    std::vector<float> mean(const renderer::PathTraceSettings& settings, int n) {
        std::vector<double> sum;
        for (int i = 0; i < n; ++i) {
            trace(settings, static_cast<std::uint32_t>(i));
            const std::vector<float> r = target.readRgba(renderer::radianceAttachment);
            sum.resize(r.size(), 0.0);
            for (std::size_t k = 0; k < r.size(); ++k) sum[k] += r[k];
        }
        std::vector<float> out(sum.size());
        for (std::size_t k = 0; k < sum.size(); ++k) out[k] = static_cast<float>(sum[k] / n);
        return out;
    }
};

double luminanceAt(const std::vector<float>& rgba, std::size_t p) {
    return 0.2126 * rgba[p * 4] + 0.7152 * rgba[p * 4 + 1] + 0.0722 * rgba[p * 4 + 2];
}

// GL rows (bottom-up) to the images' top-down rows, as FrameImages holds them.
std::vector<float> topDown(const std::vector<float>& rgba) {
    std::vector<float> out(rgba.size());
    const std::size_t row = static_cast<std::size_t>(imageSize) * 4;
    for (std::size_t y = 0; y < static_cast<std::size_t>(imageSize); ++y)
        std::memcpy(&out[y * row], &rgba[(static_cast<std::size_t>(imageSize) - 1 - y) * row], row * sizeof(float));
    return out;
}

} // namespace

class TestLobeSplit : public QObject {
    Q_OBJECT
    std::unique_ptr<Harness> h_;

private slots:
    void initTestCase() { h_ = std::make_unique<Harness>(); }

    // Four samples of the glossy room, each traced three times: the plain variant (what Accumulate
    // and Reference run), the split variant, and the split variant's diffuse view. Tolerances:
    // radiance identical bit for bit with and without the split; diffuse + specular equal to the
    // radiance within 1e-5 relative (float rounding of differently ordered sums); no specular
    // part on the pure Lambert box (exactly 0) and no diffuse part on the mirror ball (exactly 0);
    // on the polished floor both lobes carry light.
    void lobesPartitionTheRadiance() {
        const GlossyRoom room = makeGlossyRoom();
        Tracer tracer(room.scene);
        renderer::PathTraceSettings plain;
        plain.bounces = 2;
        renderer::PathTraceSettings split = plain;
        split.splitLobes = true;
        renderer::PathTraceSettings diffuseView = split;
        diffuseView.view = renderer::DebugView::DiffuseRadiance;
        double worst = 0.0, floorDiffuse = 0.0, floorSpecular = 0.0;
        int boxPixels = 0, mirrorPixels = 0;
        for (std::uint32_t sample = 0; sample < 4; ++sample) {
            tracer.trace(plain, sample);
            const auto radiance = tracer.target.readRgba(renderer::radianceAttachment);
            const auto plainSpecular = tracer.target.readRgba(renderer::specularRadianceAttachment);
            tracer.trace(split, sample);
            const auto splitRadiance = tracer.target.readRgba(renderer::radianceAttachment);
            const auto specular = tracer.target.readRgba(renderer::specularRadianceAttachment);
            const auto ids = tracer.target.readRgba(renderer::objectIdAttachment);
            const auto roughness = tracer.target.readRgba(renderer::specularAlbedoAttachment);
            tracer.trace(diffuseView, sample);
            const auto diffuse = tracer.target.readRgba(renderer::radianceAttachment);
            QVERIFY(radiance == splitRadiance);
            QCOMPARE(*std::max_element(plainSpecular.begin(), plainSpecular.end()), 1.0f); // rgb 0, a 1
            for (std::size_t p = 0; p * 4 < radiance.size(); ++p) {
                for (std::size_t c = 0; c < 3; ++c) {
                    const double r = radiance[p * 4 + c], d = diffuse[p * 4 + c], s = specular[p * 4 + c];
                    worst = std::max(worst, std::abs(d + s - r) / std::max(r, 1.0));
                    QVERIFY2(s <= r && d >= 0.0, qPrintable(QString("pixel %1: %2 + %3 vs %4").arg(p).arg(d).arg(s).arg(r)));
                }
                const float id = ids[p * 4];
                if (id == static_cast<float>(room.box.value)) {
                    ++boxPixels;
                    QCOMPARE(luminanceAt(specular, p), 0.0);
                }
                if (id == static_cast<float>(room.mirrorBall.value)) {
                    ++mirrorPixels;
                    QCOMPARE(luminanceAt(diffuse, p), 0.0);
                }
                if (std::abs(roughness[p * 4 + 3] - 0.1f) < 1e-6f) {
                    floorDiffuse += luminanceAt(diffuse, p);
                    floorSpecular += luminanceAt(specular, p);
                }
            }
        }
        qInfo("diffuse + specular vs radiance: worst relative difference %.3g; floor: diffuse %.1f, specular %.1f (sums)",
              worst, floorDiffuse, floorSpecular);
        QVERIFY(boxPixels > 0 && mirrorPixels > 0);
        QVERIFY2(worst < 1e-5, qPrintable(QString::number(worst)));
        QVERIFY(floorDiffuse > 0.0 && floorSpecular > 0.05 * floorDiffuse);
    }

    // The polished floor reflects the red box, the balls and the wall. Full's relMSE against a
    // 256-spp image after 8 and 32 frames, overall and on the floor, next to a raw 1-spp frame's and
    // the raw 32-sample mean's (figures for docs/DENOISING.md). Tolerance: at frame 8 Full is below
    // 0.5x raw overall and below raw on the floor; at frame 32, when Full shows the filtered 32-sample
    // mean, the floor's error is below the raw 32-sample mean's and not above its frame-8 error
    // (+25 %). (A raw 1-spp frame is no yardstick for later frames: one caustic sample in it can
    // move its error tenfold from seed to seed.)
    void glossyFloorBeforeConvergence() {
        const GlossyRoom room = makeGlossyRoom();
        const auto camera = cameraAt(room.scene, 0.0f);
        const auto reference = h_->converged(room.scene, camera, 256);
        dump(reference, "glossy_reference");
        h_->frames.setSettings(settingsFor(renderer::Configuration::Accumulate));
        h_->frames.setScene(room.scene);
        const auto raw = h_->frame(camera);
        const auto roughness = h_->frames.readImages().specularAlbedo;
        std::vector<bool> floor(roughness.size() / 4);
        for (std::size_t p = 0; p < floor.size(); ++p) floor[p] = std::abs(roughness[p * 4 + 3] - 0.1f) < 1e-6f;
        h_->frames.setSettings(settingsFor(renderer::Configuration::Full));
        h_->frames.setScene(room.scene);
        double full[2] = {}, fullFloor[2] = {};
        for (int f = 1; f <= 32; ++f) {
            const auto image = h_->frame(camera);
            if (f != 8 && f != 32) continue;
            const int k = f == 8 ? 0 : 1;
            full[k] = relMse(image, reference);
            fullFloor[k] = relMse(image, reference, floor);
            dump(image, "glossy_full_" + std::to_string(f));
        }
        h_->frames.setSettings(settingsFor(renderer::Configuration::Accumulate));
        h_->frames.setScene(room.scene);
        std::vector<float> mean32;
        for (int f = 1; f <= 32; ++f) mean32 = h_->frame(camera);
        const double rawAll = relMse(raw, reference), rawFloor = relMse(raw, reference, floor);
        const double mean32Floor = relMse(mean32, reference, floor);
        qInfo("glossy room, Full relMSE: frame 8 %.4f (floor %.4f), frame 32 %.4f (floor %.4f); raw 1 spp %.4f (floor %.4f); "
              "raw 32-sample mean %.4f (floor %.4f)",
              full[0], fullFloor[0], full[1], fullFloor[1], rawAll, rawFloor, relMse(mean32, reference), mean32Floor);
        QVERIFY(full[0] < 0.5 * rawAll);
        QVERIFY(fullFloor[0] < rawFloor);
        QVERIFY(fullFloor[1] < mean32Floor);
        QVERIFY(fullFloor[1] < 1.25 * fullFloor[0]);
    }

    // Baseline (bounces 0) misses the light of the bounces; its ambient term (short AO rays times
    // the environment, times diffuse albedo) stands in for it. Indirectly lit pixels: where direct
    // light is under half the reference (shadows, the wall's foot). Tolerance: over those pixels,
    // Baseline's mean luminance after 16 frames is closer to the 128-spp reference's than the mean
    // of 16 direct-only samples without the term.
    void ambientTermBrightensIndirectLight() {
        const GlossyRoom room = makeGlossyRoom();
        Tracer tracer(room.scene);
        renderer::PathTraceSettings direct;
        direct.bounces = 0;
        const auto withoutTerm = topDown(tracer.mean(direct, 16));
        renderer::PathTraceSettings full;
        full.bounces = 2;
        const auto reference = topDown(tracer.mean(full, 128));
        h_->frames.setSettings(settingsFor(renderer::Configuration::Baseline));
        h_->frames.setScene(room.scene);
        std::vector<float> baseline;
        for (int f = 0; f < 16; ++f) baseline = h_->frame(cameraAt(room.scene, 0.0f));
        double sums[3] = {};
        int count = 0;
        for (std::size_t p = 0; p * 4 < reference.size(); ++p) {
            if (!(luminanceAt(withoutTerm, p) < 0.5 * luminanceAt(reference, p))) continue;
            sums[0] += luminanceAt(withoutTerm, p);
            sums[1] += luminanceAt(baseline, p);
            sums[2] += luminanceAt(reference, p);
            ++count;
        }
        const double noTerm = sums[0] / count, withTerm = sums[1] / count, ref = sums[2] / count;
        qInfo("indirectly lit pixels (%d): mean luminance without the term %.4f, Baseline %.4f, reference %.4f", count,
              noTerm, withTerm, ref);
        QVERIFY(count > 20);
        QVERIFY(std::abs(withTerm - ref) < std::abs(noTerm - ref));
    }

    // The converging configurations never run the ambient term or the split: their first frame is
    // bit for bit the plain path-traced sample (same seed and sample index), and only Baseline's
    // traits ask for the term.
    void convergingConfigurationsAreUntouched() {
        const GlossyRoom room = makeGlossyRoom();
        Tracer tracer(room.scene);
        renderer::PathTraceSettings plain;
        plain.bounces = 2;
        tracer.trace(plain, 0);
        const auto sample = topDown(tracer.target.readRgba(renderer::radianceAttachment));
        for (auto c : {renderer::Configuration::Accumulate, renderer::Configuration::Reference}) {
            renderer::FrameRenderer frames;
            frames.setSettings(settingsFor(c));
            frames.setScene(room.scene);
            frames.renderFrame();
            QVERIFY2(frames.readImages().radiance == sample, renderer::configurationName(c).data());
        }
        for (auto c : {renderer::Configuration::Realistic, renderer::Configuration::Full, renderer::Configuration::Heavy,
                       renderer::Configuration::Accumulate, renderer::Configuration::Reference})
            QVERIFY(!renderer::traitsOf(c).ao);
        QVERIFY(renderer::traitsOf(renderer::Configuration::Baseline).ao);
    }
};

QTEST_APPLESS_MAIN(TestLobeSplit)
#include "test_lobe_split.moc"
