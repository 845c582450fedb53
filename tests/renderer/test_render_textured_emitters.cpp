// Emissive-textured mesh triangles as lights: next-event estimation picks them by their material's
// mean emission and each sample carries the texel's emission at the sampled point. A lamp whose
// texture is white on one half and black on the other must light the floor as two untextured
// quads do (white emitting, black dark), with far less noise than BSDF sampling alone (which is
// all such lamps had before).
#include "error_share.h"
#include "image_stats.h"
#include "test_render_textures_scenes.h"

#include "renderer/gpu_scene/packed_scene.h"
#include "renderer/gpu_scene/texture_refs.h"
#include "renderer/gpu_scene/texture_set.h"

#include <QTest>

#include <memory>

using namespace glint;
using namespace glint::test;

namespace {

constexpr int kSize = 32;
const glm::vec3 kEmission(3.0f);

// 64x32 texels: the half at -X (u < 0.5) white, the other black. Nearest filtering without mip
// levels, so every hit sees the sharp edge the two-quad scene has.
Texels halfWhite() {
    Texels t{64, 32, {}};
    for (int y = 0; y < t.height; ++y)
        for (int x = 0; x < t.width; ++x) {
            const std::uint8_t v = x < t.width / 2 ? 255 : 0;
            t.rgba.insert(t.rgba.end(), {v, v, v, 255});
        }
    return t;
}

// Facing down, 1 m over a white floor: the quad meshes are made facing +Y.
const glm::quat kFacingDown = glm::angleAxis(glm::pi<float>(), glm::vec3(1.0f, 0.0f, 0.0f));

// The floor, a black sky and a camera under the lamp's plane that sees the floor only (the lamps
// differ where they are seen: a single-sided black quad is culled from behind, an emitter not).
Scene room() {
    Scene scene;
    scene.settings.environment.color = glm::vec3(0.0f);
    addShape(scene, ShapeKind::GroundPlane, scene.materials.add(lambert(glm::vec3(0.8f))), glm::vec3(0.0f));
    addPerspectiveCamera(scene, {0.0f, 0.6f, 2.5f}, {0.0f, 0.0f, 0.0f}, 0.6f);
    return scene;
}

Scene texturedLamp() {
    Scene scene = room();
    Sampler nearest = sampler(Filter::Nearest, Wrap::ClampToEdge, Wrap::ClampToEdge);
    nearest.minFilter = Filter::Nearest;
    Material lamp = lambert(glm::vec3(0.0f), kEmission);
    lamp.emissiveTexture = ref(addTexture(scene, halfWhite(), nearest));
    addNode(scene, "lamp", MeshInstance{scene.meshes.add(texturedQuad(1.0f, scene.materials.add(lamp)))}, {0.0f, 1.0f, 0.0f},
            kFacingDown);
    return scene;
}

// The same light as two untextured halves: u < 0.5 lies at -X.
Scene twoQuadLamp() {
    Scene scene = room();
    const MaterialId white = scene.materials.add(lambert(glm::vec3(0.0f), kEmission));
    const MaterialId black = scene.materials.add(lambert(glm::vec3(0.0f)));
    addNode(scene, "white half", MeshInstance{scene.meshes.add(texturedQuad(1.0f, white))}, {-0.25f, 1.0f, 0.0f}, kFacingDown,
            {0.5f, 1.0f, 1.0f});
    addNode(scene, "black half", MeshInstance{scene.meshes.add(texturedQuad(1.0f, black))}, {0.25f, 1.0f, 0.0f}, kFacingDown,
            {0.5f, 1.0f, 1.0f});
    return scene;
}

// Means of 8x8-pixel blocks, channel 1: the floor's light pattern with the noise averaged down.
std::vector<double> blockMeans(const std::vector<float>& rgba) {
    std::vector<double> blocks((kSize / 8) * (kSize / 8), 0.0);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) blocks[(y / 8) * (kSize / 8) + x / 8] += pixel(rgba, kSize, x, y, 1) / 64.0;
    return blocks;
}

} // namespace

class TestRenderTexturedEmitters : public QObject {
    Q_OBJECT
    std::unique_ptr<renderer::OfflineRenderer> renderer_;

    std::vector<float> render(const Scene& scene, int spp, std::uint32_t seed,
                              renderer::AreaLightStrategy strategy = renderer::AreaLightStrategy::Mis) {
        renderer::RenderRequest request = stillRequest(kSize, spp, seed, 0);
        request.tonemapper = Tonemapper::None;
        request.areaLightStrategy = strategy;
        return renderer_->render(scene, request).radiance;
    }

private slots:
    void initTestCase() { renderer_ = std::make_unique<renderer::OfflineRenderer>(); }
    void cleanupTestCase() { renderer_.reset(); }

    // Light sampling assumes the factor times the texture's mean colour (here half of white), and
    // the material record's emissive reference carries that luminance for the MIS weight of
    // BSDF-sampled hits.
    void lightSamplingAssumesTheTexturesMean() {
        const Scene scene = texturedLamp();
        Material lamp;
        for (const auto& [id, material] : scene.materials)
            if (material.emissiveTexture.valid()) lamp = material;
        QVERIFY(lamp.emissiveTexture.valid());
        renderer::TextureSet textures;
        textures.meanOf[{scene.textures.at(lamp.emissiveTexture.texture).image, true}] = glm::vec3(0.5f);
        QCOMPARE(renderer::sampledEmission(scene, lamp, &textures), 0.5f * kEmission);
        QCOMPARE(renderer::sampledEmission(scene, lamp, nullptr), glm::vec3(0.0f)); // no texture set: not sampled
        const std::vector<glm::vec4> texels = renderer::packMaterial(lamp, &scene, &textures);
        QVERIFY(std::abs(texels[renderer::materialBaseTexels + renderer::textureRefTexels * renderer::emissiveRef + 2].w - 1.5f) < 1e-6f);
        QCOMPARE(texels[5].w, 0.0f); // that of area lights' materials: front face only
    }

    // 32x32, direct light only (0 bounces). Against the two-quad lamp at 512 spp: the textured lamp
    // at 512 spp has the same mean within 1 % and the same 8x8-block pattern within 3 % (the
    // light is where the texture is white). At 16 spp its relMSE is under a tenth of BSDF
    // sampling's alone (measured: 0.0073 against 0.27) and within 10x the two-quad lamp's (0.0013):
    // half its light samples land on black texels, which only a sampler by texels would avoid.
    void aTexturedLampLightsAsItsTexelsDo() {
        const std::vector<float> reference = render(twoQuadLamp(), 512, 1);
        const std::vector<float> textured = render(texturedLamp(), 512, 1);
        const double ratio = luminanceMean(textured) / luminanceMean(reference);
        qInfo("mean: textured %.5f, two quads %.5f, ratio %.4f", luminanceMean(textured), luminanceMean(reference), ratio);
        QVERIFY2(std::abs(ratio - 1.0) < 0.01, qPrintable(QString::number(ratio)));
        const std::vector<double> a = blockMeans(textured), b = blockMeans(reference);
        for (std::size_t i = 0; i < a.size(); ++i)
            QVERIFY2(std::abs(a[i] - b[i]) <= 0.03 * std::max(b[i], 0.02), qPrintable(QString("block %1: %2 vs %3").arg(i).arg(a[i]).arg(b[i])));

        const double texturedError = errorShare(render(texturedLamp(), 16, 2), reference).relMse;
        const double quadsError = errorShare(render(twoQuadLamp(), 16, 2), reference).relMse;
        const double bsdfError = errorShare(render(texturedLamp(), 16, 2, renderer::AreaLightStrategy::BsdfOnly), reference).relMse;
        qInfo("relMSE at 16 spp: textured %.5f, two quads %.5f, textured by BSDF sampling alone %.5f", texturedError, quadsError,
              bsdfError);
        QVERIFY2(texturedError < 0.1 * bsdfError, qPrintable(QString::number(texturedError)));
        QVERIFY2(texturedError < 10.0 * quadsError, qPrintable(QString::number(texturedError)));
    }
};

QTEST_APPLESS_MAIN(TestRenderTexturedEmitters)
#include "test_render_textured_emitters.moc"
