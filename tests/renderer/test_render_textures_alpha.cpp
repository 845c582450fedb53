// Alpha, sidedness, normal maps, vertex colours and a real textured model. Scenes are lit so that
// pixels have closed forms: emissive backgrounds seen through cut-outs, a sun over a Lambert plane
// (radiance = albedo / pi x E x cos, E = lux / 683), a uniform white environment over a pure
// Lambert quad (radiance = albedo).
#include "image_stats.h"
#include "test_render_textures_scenes.h"

#include "renderer/frame_renderer.h"
#include "renderer/gl/headless_context.h"
#include "scene/history/asset_commands.h"
#include "scene/io/scene_io.h"

#include <QTest>

#include <cmath>
#include <memory>

using namespace glint;
using namespace glint::test;

namespace {

constexpr float kPi = 3.14159265358979f;

// Emits `colour` from a black (non-reflecting) surface.
Material emitter(glm::vec3 colour) { return lambert(glm::vec3(0.0f), colour); }

// Texels whose alpha is 0 in the left half (u < 0.5) and 255 in the right half.
Texels halfCutOut() { return {2, 1, {255, 255, 255, 0, 255, 255, 255, 255}}; }

// A green-emitting quad filling the view above a red-emitting ground.
Scene quadOverRedGround(const Material& quad) {
    Scene scene;
    addShape(scene, ShapeKind::GroundPlane, scene.materials.add(emitter({1.0f, 0.0f, 0.0f})), {0.0f, -1.0f, 0.0f});
    addQuad(scene, texturedQuad(1.0f, scene.materials.add(quad)));
    addTopCamera(scene, 0.5f);
    return scene;
}

} // namespace

class TestRenderTexturesAlpha : public QObject {
    Q_OBJECT
    std::unique_ptr<renderer::OfflineRenderer> renderer_;

private slots:
    void initTestCase() { renderer_ = std::make_unique<renderer::OfflineRenderer>(); }
    void cleanupTestCase() { renderer_.reset(); }

    // 16x16, 2 spp, seed 11. MASK with cutoff 0.5 and a texture transparent in its left half: the
    // left half shows the red ground behind, the right half the green quad (1e-4).
    void alphaMaskShowsWhatIsBehind() {
        Material quad = emitter({0.0f, 1.0f, 0.0f});
        quad.alphaMode = AlphaMode::Mask;
        quad.alphaCutoff = 0.5f;
        Scene built = quadOverRedGround(quad);
        Material& m = built.materials.at(std::prev(built.materials.end())->first);
        m.baseColorTexture = ref(addTexture(built, halfCutOut(), sampler(Filter::Nearest)));
        const auto out = renderScene(*renderer_, built, 16, 2, 11);
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x) {
                const bool cut = x < 8;
                QVERIFY2(std::abs(pixel(out.radiance, 16, x, y, 0) - (cut ? 1.0f : 0.0f)) < 1e-4 &&
                             std::abs(pixel(out.radiance, 16, x, y, 1) - (cut ? 0.0f : 1.0f)) < 1e-4,
                         qPrintable(QString("pixel %1,%2").arg(x).arg(y)));
            }
    }

    // 16x16, 64 spp, seed 12. BLEND with alpha 0.25 (factor only): stochastic transparency keeps the
    // quad with probability 0.25, so the image mean is 0.25 green + 0.75 red (within 0.02).
    void alphaBlendIsStochasticCoverage() {
        Material quad = emitter({0.0f, 1.0f, 0.0f});
        quad.baseColorFactor.w = 0.25f;
        quad.alphaMode = AlphaMode::Blend;
        const auto out = renderScene(*renderer_, quadOverRedGround(quad), 16, 64, 12);
        const double red = channelStats(out.radiance, 0).mean;
        const double green = channelStats(out.radiance, 1).mean;
        QVERIFY2(std::abs(green - 0.25) < 0.02 && std::abs(red - 0.75) < 0.02, qPrintable(QString("red %1, green %2").arg(red).arg(green)));
    }

    // 32x32, 1 spp, seed 13. A sun of 683 lux shining down at 45 degrees past a masked quad (out of
    // view) onto a white Lambert ground: where the quad's cut-out half casts its shadow the ground
    // is lit, 1/pi x cos 45 (within 1e-3); behind the opaque half it is black (shadow rays respect alpha).
    void shadowRaysRespectAlphaMask() {
        Scene scene;
        addShape(scene, ShapeKind::GroundPlane, scene.materials.add(lambert(glm::vec3(1.0f))), glm::vec3(0.0f));
        Material quad = lambert(glm::vec3(1.0f));
        quad.alphaMode = AlphaMode::Mask;
        quad.baseColorTexture = ref(addTexture(scene, halfCutOut(), sampler(Filter::Nearest)));
        addQuad(scene, texturedQuad(2.0f, scene.materials.add(quad)), {-2.5f, 2.5f, 0.0f});
        addSun(scene, glm::normalize(glm::vec3(1.0f, -1.0f, 0.0f)), 683.0f);
        addTopCamera(scene, 0.9f, 5.0f);
        const auto out = renderScene(*renderer_, scene, 32, 1, 13);
        const float lit = std::cos(0.25f * kPi) / kPi;
        for (int x = 0; x < 32; ++x) {
            if (x == 15 || x == 16) continue; // the shadow's edge
            const float expected = x < 16 ? lit : 0.0f;
            const float got = pixel(out.radiance, 32, x, 16, 1);
            QVERIFY2(std::abs(got - expected) < 1e-3, qPrintable(QString("column %1: %2 vs %3").arg(x).arg(got).arg(expected)));
        }
    }

    // 16x16, 1 spp, seed 14. A sun straight down (683 pi lux: irradiance pi) on a white Lambert quad
    // whose normal map holds the tangent-space normal (204, 128, 230)/255 * 2 - 1 along the tangent
    // +X and bitangent -Z: radiance = the mapped normal's cosine to the sun, 0.8014 (within 0.2 %);
    // the same quad without the map shows 1.
    void normalMapTiltsShadingAsPredicted() {
        const auto render = [&](bool mapped) {
            Scene scene;
            Material m = lambert(glm::vec3(1.0f));
            if (mapped) m.normalTexture = ref(addTexture(scene, Texels{1, 1, {204, 128, 230, 255}}, sampler(Filter::Linear)));
            addQuad(scene, texturedQuad(1.0f, scene.materials.add(m)));
            addSun(scene, {0.0f, -1.0f, 0.0f}, 683.0f * kPi);
            addTopCamera(scene, 0.5f);
            return channelStats(renderScene(*renderer_, scene, 16, 1, 14).radiance, 0).mean;
        };
        const glm::vec3 c = glm::vec3(204.0f, 128.0f, 230.0f) / 255.0f * 2.0f - 1.0f;
        const glm::vec3 world = glm::vec3(1, 0, 0) * c.x + glm::vec3(0, 0, -1) * c.y + glm::vec3(0, 1, 0) * c.z;
        const double expected = glm::normalize(world).y;
        const double flat = render(false);
        const double mapped = render(true);
        QVERIFY2(std::abs(flat - 1.0) < 2e-3, qPrintable(QString::number(flat)));
        QVERIFY2(std::abs(mapped - expected) < 2e-3 * expected, qPrintable(QString("%1 vs %2").arg(mapped).arg(expected)));
    }

    // 16x16, 1 spp, seed 15. A white quad turned to face down, over a red-emitting ground, seen from
    // above (its back): single-sided, camera rays pass through and show red (1e-4); double-sided,
    // the quad hides the ground and, unlit, shows black.
    void singleSidedBackFacesAreCulledForCameraRays() {
        const auto render = [&](bool doubleSided) {
            Scene scene;
            addShape(scene, ShapeKind::GroundPlane, scene.materials.add(emitter({1.0f, 0.0f, 0.0f})), {0.0f, -1.0f, 0.0f});
            Material m = lambert(glm::vec3(1.0f));
            m.doubleSided = doubleSided;
            addNode(scene, "quad", MeshInstance{scene.meshes.add(texturedQuad(1.0f, scene.materials.add(m)))}, glm::vec3(0.0f),
                    glm::angleAxis(kPi, glm::vec3(1.0f, 0.0f, 0.0f)));
            addTopCamera(scene, 0.5f);
            return channelStats(renderScene(*renderer_, scene, 16, 1, 15).radiance, 0);
        };
        const ChannelStats single = render(false);
        const ChannelStats twoSided = render(true);
        QVERIFY2(std::abs(single.minimum - 1.0) < 1e-4 && std::abs(single.maximum - 1.0) < 1e-4, qPrintable(QString::number(single.mean)));
        QVERIFY2(twoSided.maximum < 1e-4, qPrintable(QString::number(twoSided.maximum)));
    }

    // 16x16, 1 spp, seed 16. COLOR_0 multiplies the base colour (no texture at all): a white-lit
    // Lambert quad shows the vertex colour (1e-4).
    void vertexColoursMultiplyBaseColour() {
        Scene scene;
        scene.settings.environment.color = glm::vec3(1.0f);
        Mesh mesh = texturedQuad(1.0f, scene.materials.add(lambert(glm::vec3(0.8f))));
        mesh.primitives[0].colors.assign(4, glm::vec4(0.5f, 1.0f, 0.25f, 1.0f));
        addQuad(scene, mesh);
        addTopCamera(scene, 0.5f);
        const auto out = renderScene(*renderer_, scene, 16, 1, 16);
        const float expected[3] = {0.4f, 0.8f, 0.2f};
        for (int c = 0; c < 3; ++c) {
            const ChannelStats s = channelStats(out.radiance, c);
            QVERIFY2(std::abs(s.minimum - expected[c]) < 1e-4 && std::abs(s.maximum - expected[c]) < 1e-4,
                     qPrintable(QString("channel %1: %2 .. %3").arg(c).arg(s.minimum).arg(s.maximum)));
        }
    }

    // 48x48, 4 spp, seed 17, 2 bounces. The bundled WaterBottle (base colour, metallic-roughness,
    // normal, emissive textures of 2048^2) under a white environment and a sun: every pixel finite and
    // non-negative, the bottle's pixels (object id != 0) textured: their albedo varies (stddev > 0.02)
    // and is not the white of an untextured material.
    void waterBottleRendersTexturedAndFinite() {
        Scene scene = loadScene(std::filesystem::path(GLINT_RESOURCES_DIR) / "scenes" / "water_bottle" / "WaterBottle.gltf").scene;
        scene.settings.environment.color = glm::vec3(1.0f);
        addSun(scene, glm::normalize(glm::vec3(-1.0f, -1.0f, -1.0f)), 2000.0f);
        addPerspectiveCamera(scene, {0.0f, 0.0f, 2.5f}, glm::vec3(0.0f), 0.8f);
        const auto out = renderScene(*renderer_, scene, 48, 4, 17, 2);
        double sum = 0.0, sum2 = 0.0;
        int onBottle = 0;
        for (std::size_t i = 0; i < out.objectId.size(); ++i) {
            for (int c = 0; c < 3; ++c) {
                const float v = out.radiance[i * 4 + static_cast<std::size_t>(c)];
                QVERIFY2(std::isfinite(v) && v >= 0.0f, qPrintable(QString("pixel %1: %2").arg(i).arg(v)));
            }
            if (out.objectId[i] == 0.0f) continue;
            const double a = out.albedo[i * 3 + 1];
            sum += a;
            sum2 += a * a;
            ++onBottle;
        }
        QVERIFY2(onBottle > 200, qPrintable(QString::number(onBottle)));
        const double mean = sum / onBottle;
        const double stddev = std::sqrt(std::max(sum2 / onBottle - mean * mean, 0.0));
        QVERIFY2(stddev > 0.02 && mean < 0.9, qPrintable(QString("albedo mean %1, stddev %2").arg(mean).arg(stddev)));
    }

    // 16x16, 1 spp, seed 15. The quad of singleSidedBackFacesAreCulledForCameraRays made double-sided
    // in place (FrameRenderer::applyChangesInPlace; a second single-sided quad outside the view keeps
    // culling compiled in, so no new variant): the triangles' culling marks follow the material, so
    // the red ground (1e-4) gives way to the black quad, and the frame equals a full rebuild of the
    // edited scene bit for bit. Last: it makes a context of its own current.
    void sidednessEditedInPlaceCullsAsAFullRebuild() {
        renderer_.reset();
        gl::HeadlessContext context;
        Scene scene;
        addShape(scene, ShapeKind::GroundPlane, scene.materials.add(emitter({1.0f, 0.0f, 0.0f})), {0.0f, -1.0f, 0.0f});
        Material single = lambert(glm::vec3(1.0f));
        single.doubleSided = false;
        const MaterialId edited = scene.materials.add(single);
        const glm::quat faceDown = glm::angleAxis(kPi, glm::vec3(1.0f, 0.0f, 0.0f));
        addNode(scene, "quad", MeshInstance{scene.meshes.add(texturedQuad(1.0f, edited))}, glm::vec3(0.0f), faceDown);
        addNode(scene, "elsewhere", MeshInstance{scene.meshes.add(texturedQuad(1.0f, scene.materials.add(single)))},
                glm::vec3(20.0f, 0.0f, 0.0f), faceDown);
        addTopCamera(scene, 0.5f);
        renderer::FrameSettings settings;
        settings.spp = 1;
        settings.bounces = 0;
        settings.seed = 15;
        settings.width = settings.height = 16;
        settings.tonemapper = Tonemapper::None;
        renderer::FrameRenderer frames;
        frames.setSettings(settings);
        frames.setCamera(renderer::resolveCamera(scene, "", 16, 16));
        frames.setScene(scene);
        const auto redRange = [&] {
            frames.renderFrame();
            const std::vector<float> radiance = frames.readImages().radiance;
            float low = 1e9f, high = -1e9f;
            for (std::size_t i = 0; i < radiance.size(); i += 4) low = std::min(low, radiance[i]), high = std::max(high, radiance[i]);
            return std::pair{low, high};
        };
        const auto [culledLow, culledHigh] = redRange();
        QVERIFY2(std::abs(culledLow - 1.0f) < 1e-4f && std::abs(culledHigh - 1.0f) < 1e-4f, qPrintable(QString::number(culledLow)));

        Material doubleSided = scene.materials.at(edited);
        doubleSided.doubleSided = true;
        QVERIFY(frames.applyChangesInPlace(scene, SetMaterial(edited, doubleSided).apply(scene)));
        frames.renderFrame();
        const std::vector<float> inPlace = frames.readImages().radiance;
        float brightest = 0.0f;
        for (std::size_t i = 0; i < inPlace.size(); i += 4) brightest = std::max(brightest, inPlace[i]);
        QVERIFY2(brightest < 1e-4f, qPrintable(QString::number(brightest)));
        frames.setScene(scene);
        frames.renderFrame();
        QVERIFY2(inPlace == frames.readImages().radiance, "the frame edited in place differs from a full rebuild");
    }
};

QTEST_APPLESS_MAIN(TestRenderTexturesAlpha)
#include "test_render_textures_alpha.moc"
