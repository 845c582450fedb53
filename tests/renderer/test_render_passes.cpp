// Render passes (docs/CLI.md, "Render passes"): written into an EXR and read back with OpenImageIO.
// - The six light passes sum to the beauty per pixel and channel, within 2e-6 relative (+1e-7
//   absolute), on a scene with every kind of light path: diffuse, glossy, emissive and glass
//   surfaces, a sun and an environment; and each pass holds light there.
// - Known answers: a Lambert-only scene has no glossy light; an emitter filling the view is all
//   Emit; an empty view of the environment is all Env; direct light only (--bounces 0) has no
//   indirect light.
// - Motion vectors: a camera sliding by a known distance, and an object sliding under a still
//   camera, give the known offsets in pixels (previous minus current, y down).
// - Without passes the EXR holds none of them and the renderer allocates nothing for them.
#include "render_scene.h"
#include "scene_builder.h"

#include "renderer/output/image_files.h"
#include "scene/anim/node_keys.h"
#include "scene/anim/scene_at_time.h"

#include <OpenImageIO/imageio.h>

#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>

using namespace glint;
using namespace glint::test;

namespace {

constexpr int kSize = 32;
const char* const kLight[] = {"DiffDir", "DiffInd", "GlossDir", "GlossInd", "Emit", "Env"};

// An EXR's channels by name, each a plane of width x height floats.
struct Exr {
    int width = 0;
    int height = 0;
    std::map<std::string, std::vector<float>> channels;
    const std::vector<float>& operator[](const std::string& name) const {
        static const std::vector<float> none;
        const auto it = channels.find(name);
        return it == channels.end() ? none : it->second;
    }
    bool has(const std::string& name) const { return channels.count(name) > 0; }
};

Exr readExr(const std::string& file) {
    Exr exr;
    auto in = OIIO::ImageInput::open(file);
    if (!in) return exr;
    const OIIO::ImageSpec& spec = in->spec();
    exr.width = spec.width;
    exr.height = spec.height;
    std::vector<float> pixels(spec.image_pixels() * std::size_t(spec.nchannels));
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data())) return exr;
    for (int c = 0; c < spec.nchannels; ++c) {
        std::vector<float>& plane = exr.channels[spec.channelnames[std::size_t(c)]];
        for (std::size_t i = 0; i < spec.image_pixels(); ++i) plane.push_back(pixels[i * std::size_t(spec.nchannels) + std::size_t(c)]);
    }
    return exr;
}

double total(const std::vector<float>& plane) {
    double sum = 0.0;
    for (float v : plane) sum += double(v);
    return sum;
}

// Every light pass's channels summed, against the beauty: the largest excess over the tolerance
// |sum - beauty| <= 2e-6 |beauty| + 1e-7 (<= 0: within it everywhere), and the largest relative error.
struct SumCheck {
    double worstExcess = -1.0;
    double worstRelative = 0.0;
};

SumCheck checkSum(const Exr& exr) {
    SumCheck check;
    for (const char* c : {"R", "G", "B"}) {
        const std::vector<float>& beauty = exr[c];
        for (std::size_t i = 0; i < beauty.size(); ++i) {
            float sum = 0.0f;
            for (const char* pass : kLight) sum += exr[std::string(pass) + "." + c][i];
            const double error = std::abs(double(sum) - double(beauty[i]));
            check.worstExcess = std::max(check.worstExcess, error - (2e-6 * std::abs(double(beauty[i])) + 1e-7));
            if (beauty[i] > 1e-3f) check.worstRelative = std::max(check.worstRelative, error / double(beauty[i]));
        }
    }
    return check;
}

double passTotal(const Exr& exr, const std::string& pass) {
    return total(exr[pass + ".R"]) + total(exr[pass + ".G"]) + total(exr[pass + ".B"]);
}

// A floor (Lambert), a rough metal sphere, a glass sphere, an emissive panel, a sun and a blue-grey
// sky, seen from above at an angle so the sky shows at the top. `diffuseOnly`: every surface Lambert.
Scene everyPath(bool diffuseOnly) {
    Scene scene;
    const MaterialId floor = scene.materials.add(lambert(glm::vec3(0.7f)));
    Material metal = mirror();
    metal.roughnessFactor = 0.3f;
    metal.baseColorFactor = glm::vec4(0.9f, 0.7f, 0.4f, 1.0f);
    const MaterialId glossy = scene.materials.add(diffuseOnly ? lambert(glm::vec3(0.9f, 0.7f, 0.4f)) : metal);
    const MaterialId clear = scene.materials.add(diffuseOnly ? lambert(glm::vec3(0.5f)) : glass(1.5f, 0.0f));
    const MaterialId glow = scene.materials.add(lambert(glm::vec3(0.2f), glm::vec3(4.0f, 3.0f, 2.0f)));
    addShape(scene, ShapeKind::Quad, floor, glm::vec3(0.0f), 0.5f, glm::vec3(6.0f, 1.0f, 6.0f));
    addShape(scene, ShapeKind::Sphere, glossy, glm::vec3(-0.6f, 0.5f, 0.0f), 0.5f);
    addShape(scene, ShapeKind::Sphere, clear, glm::vec3(0.6f, 0.5f, 0.2f), 0.45f);
    addShape(scene, ShapeKind::Quad, glow, glm::vec3(0.0f, 0.3f, -1.2f), 0.5f, glm::vec3(1.0f, 1.0f, 0.5f),
             glm::angleAxis(glm::radians(60.0f), glm::vec3(1.0f, 0.0f, 0.0f)));
    addSun(scene, glm::vec3(-0.3f, -1.0f, -0.4f), 2.0f);
    scene.settings.environment.color = glm::vec3(0.3f, 0.4f, 0.6f);
    addPerspectiveCamera(scene, glm::vec3(0.0f, 1.6f, 3.0f), glm::vec3(0.0f, 0.2f, -0.5f), glm::radians(55.0f));
    return scene;
}

} // namespace

class TestRenderPasses : public QObject {
    Q_OBJECT
    std::unique_ptr<renderer::OfflineRenderer> renderer_;
    QTemporaryDir dir_;

    // Renders with every pass and reads the EXR back.
    Exr render(const Scene& scene, renderer::RenderRequest request, const char* name) {
        request.renderPasses = true;
        const renderer::RenderOutput image = renderer_->render(scene, request);
        renderer::ExrLayers layers = renderer::parseAovList("none");
        layers.passes = renderer::parsePassList("all");
        const std::string file = dir_.filePath(name).toStdString();
        renderer::writeRenderImage(file, image, layers, {});
        return readExr(file);
    }

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        renderer_ = std::make_unique<renderer::OfflineRenderer>();
    }
    void cleanupTestCase() { renderer_.reset(); }

    void theLightPassesSumToTheBeauty() {
        const Exr exr = render(everyPath(false), stillRequest(kSize, 16, 3, 4), "every_path.exr");
        QCOMPARE(exr.width, kSize);
        for (const char* pass : kLight)
            for (const char* c : {".R", ".G", ".B"}) QVERIFY2(exr.has(std::string(pass) + c), pass);
        QVERIFY(exr.has("Vector.X") && exr.has("Vector.Y"));
        for (const char* pass : kLight) // each kind of path is in the picture
            QVERIFY2(passTotal(exr, pass) > 1e-3, qPrintable(QString("%1 holds no light").arg(pass)));
        const SumCheck check = checkSum(exr);
        qInfo("sum of the light passes against the beauty: largest relative error %.3g", check.worstRelative);
        QVERIFY2(check.worstExcess <= 0.0, qPrintable(QString("off by %1 beyond the tolerance").arg(check.worstExcess)));
    }

    // Participating media (docs/MEDIA.md): fog (falling with height) and a scattering volume in the
    // glass sphere's place. Light scattered in them is counted by the same passes (a scatter is a
    // diffuse-like vertex), so the sum still holds.
    void theSumHoldsInFogAndVolumes() {
        Scene scene = everyPath(false);
        scene.settings.fog = {.density = 0.4f, .color = glm::vec3(0.9f), .anisotropy = 0.5f, .heightFalloff = 0.5f};
        Material smoke = glass(1.0f, 1.0f);
        smoke.attenuationColor = glm::vec3(0.3f, 0.5f, 0.7f);
        smoke.attenuationDistance = 0.3f;
        smoke.scatterColor = glm::vec3(0.8f);
        addShape(scene, ShapeKind::Sphere, scene.materials.add(smoke), glm::vec3(0.0f, 0.4f, 0.6f), 0.35f);
        const Exr exr = render(scene, stillRequest(kSize, 16, 5, 4), "media.exr");
        const SumCheck check = checkSum(exr);
        qInfo("in fog: largest relative error %.3g", check.worstRelative);
        QVERIFY2(check.worstExcess <= 0.0, qPrintable(QString("off by %1 beyond the tolerance").arg(check.worstExcess)));
    }

    // The clamp scales every pass as it scales the radiance, so the sum still holds.
    void theSumHoldsUnderTheClamp() {
        renderer::RenderRequest request = stillRequest(kSize, 8, 4, 4);
        request.clamp = 0.5f;
        const SumCheck check = checkSum(render(everyPath(false), request, "clamped.exr"));
        QVERIFY2(check.worstExcess <= 0.0, qPrintable(QString("off by %1 beyond the tolerance").arg(check.worstExcess)));
    }

    void aLambertSceneHasNoGlossyLight() {
        const Exr exr = render(everyPath(true), stillRequest(kSize, 8, 5, 4), "lambert.exr");
        QCOMPARE(passTotal(exr, "GlossDir"), 0.0);
        QCOMPARE(passTotal(exr, "GlossInd"), 0.0);
        QVERIFY(passTotal(exr, "DiffDir") > 0.0 && passTotal(exr, "DiffInd") > 0.0);
        QVERIFY(checkSum(exr).worstExcess <= 0.0);
    }

    void directLightOnlyHasNoIndirectLight() {
        const Exr exr = render(everyPath(false), stillRequest(kSize, 8, 6, 0), "direct.exr");
        QCOMPARE(passTotal(exr, "DiffInd"), 0.0);
        QCOMPARE(passTotal(exr, "GlossInd"), 0.0);
        QVERIFY(passTotal(exr, "DiffDir") > 0.0 && passTotal(exr, "GlossDir") > 0.0);
        QVERIFY(checkSum(exr).worstExcess <= 0.0);
    }

    // A black emitter filling an orthographic view: every pixel is its emission, all in Emit.
    void anEmitterSeenDirectlyIsAllEmit() {
        Scene scene;
        const MaterialId glow = scene.materials.add(lambert(glm::vec3(0.0f), glm::vec3(1.0f, 2.0f, 3.0f)));
        addShape(scene, ShapeKind::Quad, glow, glm::vec3(0.0f), 0.5f, glm::vec3(4.0f, 1.0f, 4.0f));
        addOrthographicCamera(scene, {0.0f, 1.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 0.5f);
        const Exr exr = render(scene, stillRequest(kSize, 4, 7, 4), "emitter.exr");
        for (const char* c : {"R", "G", "B"}) QCOMPARE(exr[std::string("Emit.") + c], exr[c]);
        QCOMPARE(exr["Emit.G"].front(), 2.0f);
        for (const char* pass : {"DiffDir", "DiffInd", "GlossDir", "GlossInd", "Env"}) QCOMPARE(passTotal(exr, pass), 0.0);
    }

    // Nothing in view but the environment: all Env, equal to its colour.
    void theEnvironmentSeenDirectlyIsAllEnv() {
        Scene scene;
        const MaterialId grey = scene.materials.add(lambert(glm::vec3(0.5f)));
        addShape(scene, ShapeKind::Sphere, grey, glm::vec3(0.0f, -10.0f, 0.0f), 0.5f); // out of view
        scene.settings.environment.color = glm::vec3(0.25f, 0.5f, 1.0f);
        addPerspectiveCamera(scene, {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, glm::radians(40.0f));
        const Exr exr = render(scene, stillRequest(kSize, 4, 8, 4), "environment.exr");
        for (const char* c : {"R", "G", "B"}) QCOMPARE(exr[std::string("Env.") + c], exr[c]);
        QCOMPARE(exr["Env.B"].front(), 1.0f);
        for (const char* pass : {"DiffDir", "DiffInd", "GlossDir", "GlossInd", "Emit"}) QCOMPARE(passTotal(exr, pass), 0.0);
    }

    // An orthographic camera 1 m across (kSize pixels) looking down slides along +X at 1 m/s and
    // along -Z (the image's up) at 0.5 m/s. A frame of 0.25 s before, a point of the floor was
    // 0.25 m = kSize / 4 pixels further right and kSize / 8 pixels higher in the image:
    // Vector = (+8, -4) pixels at kSize 32.
    void aMovingCameraGivesItsOffsetInPixels() {
        Scene scene;
        const MaterialId grey = scene.materials.add(lambert(glm::vec3(0.5f), glm::vec3(0.5f)));
        addShape(scene, ShapeKind::Quad, grey, glm::vec3(0.0f), 0.5f, glm::vec3(20.0f, 1.0f, 20.0f));
        const NodeId camera = addOrthographicCamera(scene, {0.0f, 1.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 0.5f);
        Transform at = scene.at(camera).local;
        Animation slide = withNodeKey({}, camera, 0.0, at, Interpolation::Linear);
        at.translation += glm::vec3(1.0f, 0.0f, -0.5f);
        scene.animations.add(withNodeKey(slide, camera, 1.0, at, Interpolation::Linear));
        renderer::RenderRequest request = stillRequest(kSize, 2, 9, 0);
        request.time = 0.5;
        request.motionSeconds = 0.25;
        const Exr exr = render(sceneAt(scene, request.time), request, "camera_motion.exr");
        for (std::size_t i = 0; i < exr["Vector.X"].size(); ++i) {
            QVERIFY2(std::abs(exr["Vector.X"][i] - kSize / 4.0f) < 1e-3f, qPrintable(QString::number(exr["Vector.X"][i])));
            QVERIFY2(std::abs(exr["Vector.Y"][i] + kSize / 8.0f) < 1e-3f, qPrintable(QString::number(exr["Vector.Y"][i])));
        }
    }

    // A still camera; a quad sliding along +X at 1 m/s. Where the quad is, Vector.X = -8 pixels
    // (0.25 s before it was 0.25 m to the left); the still floor below moves by 0.
    void aMovingObjectGivesItsOffsetInPixels() {
        Scene scene;
        const MaterialId grey = scene.materials.add(lambert(glm::vec3(0.5f), glm::vec3(0.5f)));
        const MaterialId glow = scene.materials.add(lambert(glm::vec3(0.0f), glm::vec3(1.0f)));
        addShape(scene, ShapeKind::Quad, grey, glm::vec3(0.0f), 0.5f, glm::vec3(20.0f, 1.0f, 20.0f));
        const NodeId quad = addShape(scene, ShapeKind::Quad, glow, glm::vec3(-0.25f, 0.2f, 0.0f), 0.5f, glm::vec3(0.5f, 1.0f, 2.0f));
        Transform at = scene.at(quad).local;
        Animation slide = withNodeKey({}, quad, 0.0, at, Interpolation::Linear);
        at.translation.x += 1.0f;
        scene.animations.add(withNodeKey(slide, quad, 1.0, at, Interpolation::Linear));
        addOrthographicCamera(scene, {0.0f, 1.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 0.5f);
        renderer::RenderRequest request = stillRequest(kSize, 2, 10, 0);
        request.time = 0.25; // the quad spans x = -0.25..0.25: the middle half of the image
        request.motionSeconds = 0.25;
        const Exr exr = render(sceneAt(scene, request.time), request, "object_motion.exr");
        int onQuad = 0;
        for (std::size_t i = 0; i < exr["Vector.X"].size(); ++i) {
            const bool quadPixel = exr["Emit.G"][i] > 0.9f;
            onQuad += quadPixel ? 1 : 0;
            const float expected = quadPixel ? -kSize / 4.0f : 0.0f;
            QVERIFY2(std::abs(exr["Vector.X"][i] - expected) < 1e-3f, qPrintable(QString("%1 at %2").arg(exr["Vector.X"][i]).arg(i)));
            QVERIFY(std::abs(exr["Vector.Y"][i]) < 1e-3f);
        }
        QVERIFY(onQuad > kSize * kSize / 4);
    }

    // Forty quads sliding along +X under a still camera: more moving objects than a shader's
    // uniform arrays would hold (they held 32; the rest read 0). Every quad's pixels read -16 (64 px).
    void manyMovingObjectsAllGetTheirOffset() {
        Scene scene;
        const MaterialId grey = scene.materials.add(lambert(glm::vec3(0.5f), glm::vec3(0.5f)));
        const MaterialId glow = scene.materials.add(lambert(glm::vec3(0.0f), glm::vec3(1.0f)));
        addShape(scene, ShapeKind::Quad, grey, glm::vec3(0.0f), 0.5f, glm::vec3(20.0f, 1.0f, 20.0f));
        Animation slide;
        for (int i = 0; i < 40; ++i) {
            const glm::vec3 start(-0.65f + 0.12f * float(i % 8), 0.2f, -0.3f + 0.12f * float(i / 8));
            const NodeId quad = addShape(scene, ShapeKind::Quad, glow, start, 0.5f, glm::vec3(0.08f, 1.0f, 0.08f));
            Transform at = scene.at(quad).local;
            slide = withNodeKey(slide, quad, 0.0, at, Interpolation::Linear);
            at.translation.x += 1.0f;
            slide = withNodeKey(slide, quad, 1.0, at, Interpolation::Linear);
        }
        scene.animations.add(slide);
        addOrthographicCamera(scene, {0.0f, 1.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 0.5f);
        const int size = 64;
        renderer::RenderRequest request = stillRequest(size, 1, 10, 0);
        request.time = 0.25;
        request.motionSeconds = 0.25;
        const Exr exr = render(sceneAt(scene, request.time), request, "many_moving.exr");
        int onQuads = 0;
        for (std::size_t i = 0; i < exr["Vector.X"].size(); ++i) {
            const bool quadPixel = exr["Emit.G"][i] > 0.9f;
            onQuads += quadPixel ? 1 : 0;
            const float expected = quadPixel ? -size / 4.0f : 0.0f;
            QVERIFY2(std::abs(exr["Vector.X"][i] - expected) < 1e-3f,
                     qPrintable(QString("%1 at pixel %2, %3").arg(exr["Vector.X"][i]).arg(i % size).arg(i / size)));
        }
        QVERIFY2(onQuads > 40 * 16, qPrintable(QString("%1 quad pixels").arg(onQuads)));
    }

    // Without passes the image has none and the render reads back none.
    void noPassesNoChannels() {
        const renderer::RenderOutput image = renderer_->render(everyPath(false), stillRequest(kSize, 1, 11, 1));
        QVERIFY(image.vectors.empty());
        for (const auto& plane : image.lightPasses) QVERIFY(plane.empty());
        const std::string file = dir_.filePath("plain.exr").toStdString();
        renderer::writeRenderImage(file, image, renderer::parseAovList("all"), {});
        const Exr exr = readExr(file);
        QVERIFY(exr.has("R") && !exr.has("Emit.R") && !exr.has("Vector.X"));
        // Asking for passes from an image rendered without them is refused, not filled with zeros.
        renderer::ExrLayers layers;
        layers.passes = renderer::parsePassList("Emit");
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, renderer::writeRenderImage(file, image, layers, {}));
    }

    void realTimeConfigurationsRefusePasses() {
        renderer::RenderRequest request = stillRequest(kSize, 1, 12, 1);
        request.configuration = renderer::Configuration::Full;
        request.renderPasses = true;
        QVERIFY_THROWS_EXCEPTION(std::runtime_error, renderer_->render(everyPath(false), request));
    }

    void passNamesParse() {
        QCOMPARE(renderer::passListName(renderer::parsePassList("all")), std::string("DiffDir,DiffInd,GlossDir,GlossInd,Emit,Env,Vector"));
        QCOMPARE(renderer::passListName(renderer::parsePassList("light")), std::string("DiffDir,DiffInd,GlossDir,GlossInd,Emit,Env"));
        QCOMPARE(renderer::passListName(renderer::parsePassList("vector,EMIT,diffdir")), std::string("DiffDir,Emit,Vector"));
        QVERIFY(!renderer::parsePassList("none").any());
        QVERIFY(!renderer::parsePassList("").any());
        try {
            renderer::parsePassList("Emit,Shadow");
            QFAIL("an unknown pass was accepted");
        } catch (const std::invalid_argument& e) {
            QVERIFY2(std::string(e.what()).find("unknown render pass 'Shadow'") != std::string::npos, e.what());
        }
    }
};

QTEST_APPLESS_MAIN(TestRenderPasses)
#include "test_render_passes.moc"
