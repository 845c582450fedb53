// Textures of KHR_materials_specular, _transmission and _volume through an orthographic camera
// looking straight down at a textured quad (test_render_textures_scenes.h): the texture's left half
// (u < 0.5) and right half hold two values, and each half must render like the material whose
// constant factor equals the factor x that texel. The references sample the same random numbers
// per pixel, so the halves agree closely; each test also checks the two references differ by far
// more than the tolerance, so a texture that is ignored fails. 32x32 pixels, 4 spp, seed 3; the two
// columns at the middle are left out (the nearest texel changes there).
#include "image_stats.h"
#include "test_render_textures_scenes.h"

#include "renderer/frame_renderer.h"
#include "renderer/gl/headless_context.h"
#include "scene/history/asset_commands.h"

#include <QTest>

#include <cmath>
#include <memory>

using namespace glint;
using namespace glint::test;

namespace {

constexpr int kSize = 32;
constexpr int kSpp = 4;
constexpr std::uint32_t kSeed = 3;

// 2x1 texels, nearest: left texel `left`, right texel `right` (RGBA).
TextureId halvesTexture(Scene& scene, glm::u8vec4 left, glm::u8vec4 right) {
    return addTexture(scene, Texels{2, 1, {left.x, left.y, left.z, left.w, right.x, right.y, right.z, right.w}},
                      sampler(Filter::Nearest));
}

// Gives every extension texture slot that `m` leaves empty a white texture, which changes nothing
// (factor x 1; thickness is not read where the factor makes the surface thin-walled): every scene
// the suite renders through the OfflineRenderer then shares one shader variant, compiled once (a
// textured program takes llvmpipe about 3 s of CPU).
void fillNeutralExtensionTextures(Scene& scene, Material& m) {
    TextureRef* refs[] = {&m.specularTexture, &m.specularColorTexture, &m.transmissionTexture, &m.thicknessTexture};
    for (TextureRef* slot : refs)
        if (!slot->valid()) *slot = ref(halvesTexture(scene, {255, 255, 255, 255}, {255, 255, 255, 255}));
}

// Mean of channel c over the left (x < 15) or right (x > 16) half.
double halfMean(const renderer::RenderOutput& out, bool left, int c) {
    double sum = 0.0;
    int n = 0;
    for (int y = 0; y < out.height; ++y)
        for (int x = left ? 0 : 17; x < (left ? 15 : out.width); ++x, ++n) sum += pixel(out.radiance, out.width, x, y, c);
    return sum / n;
}

// Share of the half's pixels whose channel c is within `tolerance` of the reference's.
double shareWithin(const renderer::RenderOutput& out, const renderer::RenderOutput& ref, bool left, int c, double tolerance) {
    int close = 0, n = 0;
    for (int y = 0; y < out.height; ++y)
        for (int x = left ? 0 : 17; x < (left ? 15 : out.width); ++x, ++n)
            close += std::abs(pixel(out.radiance, out.width, x, y, c) - pixel(ref.radiance, ref.width, x, y, c)) <= tolerance;
    return double(close) / n;
}

// The quad with `textured` in front of `background` (which may add lights), seen from above.
Scene quadScene(const Material& textured, const std::function<void(Scene&)>& background, const std::function<void(Scene&, Material&)>& texture) {
    Scene scene;
    Material m = textured;
    if (texture) texture(scene, m);
    fillNeutralExtensionTextures(scene, m); // references too: one variant for every render
    addQuad(scene, texturedQuad(1.0f, scene.materials.add(m)));
    if (background) background(scene);
    addTopCamera(scene, 0.5f);
    return scene;
}

} // namespace

class TestRenderTexturesExt : public QObject {
    Q_OBJECT
    std::unique_ptr<renderer::OfflineRenderer> renderer_;

    renderer::RenderOutput render(const Scene& scene, int bounces = 0) { return renderScene(*renderer_, scene, kSize, kSpp, kSeed, bounces); }

    // Left half like `leftRef`, right half like `rightRef` (channel means within 0.002, and 95 % of
    // the pixels within 1e-3), and the references' halves at least `minContrast` apart.
    void checkHalves(const renderer::RenderOutput& out, const renderer::RenderOutput& leftRef, const renderer::RenderOutput& rightRef,
                     double minContrast) {
        for (int c = 0; c < 3; ++c)
            for (const bool left : {true, false}) {
                const renderer::RenderOutput& ref = left ? leftRef : rightRef;
                const renderer::RenderOutput& other = left ? rightRef : leftRef;
                const QString where = QString("%1 half, channel %2").arg(left ? "left" : "right").arg(c);
                QVERIFY2(std::abs(halfMean(out, left, c) - halfMean(ref, left, c)) < 0.002,
                         qPrintable(where + QString(": %1, reference %2").arg(halfMean(out, left, c)).arg(halfMean(ref, left, c))));
                QVERIFY2(shareWithin(out, ref, left, c, 1e-3) >= 0.95, qPrintable(where + ": pixels differ from the reference"));
                if (c == 0)
                    QVERIFY2(std::abs(halfMean(other, left, c) - halfMean(ref, left, c)) > minContrast,
                             qPrintable(where + ": the references are too alike to tell the texture is read"));
            }
    }

private slots:
    void initTestCase() { renderer_ = std::make_unique<renderer::OfflineRenderer>(); }
    void cleanupTestCase() { renderer_.reset(); }

    // specularFactor 1 x texture A: 0 on the left is pure Lambert (the specularFactor 0 reference),
    // 1 on the right the full layer. Dark grey rough dielectric under a white sky: the layer adds
    // about 0.04 there.
    void specularTextureZeroIsLambert() {
        Material m = lambert(glm::vec3(0.2f));
        m.specularFactor = 1.0f;
        m.roughnessFactor = 0.4f;
        m.doubleSided = true; // the variant of the other tests here: fewer programs to compile
        const auto sky = [](Scene& s) { s.settings.environment.color = glm::vec3(1.0f); };
        const auto out = render(quadScene(m, sky, [](Scene& s, Material& mm) {
            mm.specularTexture = ref(halvesTexture(s, {255, 255, 255, 0}, {0, 0, 0, 255}));
        }));
        Material lambertRef = m, fullRef = m;
        lambertRef.specularFactor = 0.0f;
        checkHalves(out, render(quadScene(lambertRef, sky, {})), render(quadScene(fullRef, sky, {})), 0.02);
    }

    // specularColorFactor 1 x texture RGB (sRGB): black on the left is the specularColorFactor 0
    // reference (F0 = 0), white on the right the default layer.
    void specularColorTextureScalesF0() {
        Material m = lambert(glm::vec3(0.2f));
        m.specularFactor = 1.0f;
        m.roughnessFactor = 0.4f;
        m.doubleSided = true; // the variant of the other tests here: fewer programs to compile
        const auto sky = [](Scene& s) { s.settings.environment.color = glm::vec3(1.0f); };
        const auto out = render(quadScene(m, sky, [](Scene& s, Material& mm) {
            mm.specularColorTexture = ref(halvesTexture(s, {0, 0, 0, 255}, {255, 255, 255, 255}));
        }));
        Material blackRef = m, whiteRef = m;
        blackRef.specularColorFactor = glm::vec3(0.0f);
        checkHalves(out, render(quadScene(blackRef, sky, {})), render(quadScene(whiteRef, sky, {})), 0.01);
    }

    // transmissionFactor 1 x texture R: 1 on the left is thin glass showing the emitter below
    // through its tint, 0 on the right the opaque base colour, dark under a black sky.
    void transmissionTextureHalves() {
        Material m = glass(1.5f, 0.0f);
        m.baseColorFactor = glm::vec4(0.9f, 0.6f, 0.3f, 1.0f);
        m.doubleSided = true;
        const auto emitterBelow = [](Scene& s) {
            Material emitter = lambert(glm::vec3(0.0f), glm::vec3(1.0f));
            emitter.doubleSided = true; // one sidedness variant for the whole suite
            addQuad(s, texturedQuad(4.0f, s.materials.add(emitter)), {0.0f, -0.5f, 0.0f});
        };
        const auto out = render(quadScene(m, emitterBelow, [](Scene& s, Material& mm) {
            mm.transmissionTexture = ref(halvesTexture(s, {255, 0, 0, 255}, {0, 255, 255, 255}));
        }), 2);
        Material glassRef = m, opaqueRef = m;
        opaqueRef.transmissionFactor = 0.0f;
        checkHalves(out, render(quadScene(glassRef, emitterBelow, {}), 2), render(quadScene(opaqueRef, emitterBelow, {}), 2), 0.5);
    }

    // thicknessFactor 1 x texture G on a closed slab 0.5 m deep (top and bottom faces) of clear glass
    // with IOR 1 (no Fresnel, no bending), attenuation colour 0.5 at distance 0.5 m, under a white
    // sky. G = 1 (right): a volume, Beer-Lambert gives exp(-ln 2 / 0.5 m x 0.5 m) = 0.5, as the
    // untextured thicknessFactor 1 reference; G = 0 (left): thin-walled where the ray enters, no
    // absorption, 1.0. Both within 0.002 of the prediction.
    void thicknessTextureSwitchesAbsorption() {
        Material m = glass(1.0f, 1.0f);
        m.attenuationColor = glm::vec3(0.5f);
        m.attenuationDistance = 0.5f;
        m.doubleSided = true;
        const auto slab = [](Scene& s, Material& mm, bool textured) {
            if (textured) mm.thicknessTexture = ref(halvesTexture(s, {0, 0, 0, 255}, {255, 255, 255, 255}));
            fillNeutralExtensionTextures(s, mm);
            const MaterialId id = s.materials.add(mm);
            addQuad(s, texturedQuad(1.0f, id));
            Mesh bottom = texturedQuad(1.0f, id);
            Primitive& p = bottom.primitives[0];
            p.normals.assign(4, glm::vec3(0.0f, -1.0f, 0.0f));
            p.indices = {0, 2, 1, 0, 3, 2}; // facing -Y: the slab's outside
            addQuad(s, bottom, {0.0f, -0.5f, 0.0f});
            s.settings.environment.color = glm::vec3(1.0f);
            addTopCamera(s, 0.5f);
        };
        Scene textured, reference;
        Material a = m, b = m;
        slab(textured, a, true);
        slab(reference, b, false);
        const auto out = render(textured, 4);
        const auto volume = render(reference, 4);
        for (int c = 0; c < 3; ++c) {
            QVERIFY2(std::abs(halfMean(out, true, c) - 1.0) < 0.002, qPrintable(QString("thin half: %1").arg(halfMean(out, true, c))));
            QVERIFY2(std::abs(halfMean(out, false, c) - 0.5) < 0.002, qPrintable(QString("thick half: %1").arg(halfMean(out, false, c))));
            QVERIFY2(std::abs(halfMean(volume, true, c) - 0.5) < 0.002, qPrintable(QString("reference: %1").arg(halfMean(volume, true, c))));
            QVERIFY(shareWithin(out, volume, false, c, 1e-3) >= 0.95);
        }
    }

    // A material edit that starts sampling a specular texture whose image the scene already uploads
    // (here as metallic-roughness: the same linear image, so no new texture set) needs another
    // shader variant: FrameRenderer must rebuild instead of updating the material buffer in place.
    // The edited frame equals a full rebuild of the edited scene (bit for bit) and differs from the
    // frame before. Last: it makes a context of its own current.
    void materialEditAddingASpecularTextureSwitchesTheVariant() {
        renderer_.reset();
        gl::HeadlessContext context;
        Scene scene;
        scene.settings.environment.color = glm::vec3(1.0f);
        const TextureId mr = halvesTexture(scene, {255, 255, 255, 0}, {255, 255, 255, 0}); // roughness 1x, metallic 1x, A 0
        Material m = lambert(glm::vec3(0.2f));
        m.specularFactor = 1.0f;
        m.roughnessFactor = 0.4f;
        m.doubleSided = true;
        m.metallicRoughnessTexture = ref(mr);
        const MaterialId id = scene.materials.add(m);
        addQuad(scene, texturedQuad(1.0f, id));
        addTopCamera(scene, 0.5f);
        renderer::FrameSettings settings;
        settings.spp = kSpp;
        settings.bounces = 0;
        settings.seed = kSeed;
        settings.width = settings.height = kSize;
        settings.tonemapper = Tonemapper::None;
        const auto frame = [&](renderer::FrameRenderer& frames) {
            frames.renderFrame();
            return frames.readImages().radiance;
        };
        renderer::FrameRenderer edited;
        edited.setSettings(settings);
        edited.setCamera(renderer::resolveCamera(scene, "", kSize, kSize));
        edited.setScene(scene);
        const std::vector<float> before = frame(edited);

        Material textured = scene.materials.at(id);
        textured.specularTexture = ref(mr);
        edited.applyChanges(scene, SetMaterial(id, textured).apply(scene));
        const std::vector<float> after = frame(edited);

        edited.setScene(scene); // a full rebuild (same programs: no second compile of the variant)
        QVERIFY2(after == frame(edited), "the edited frame differs from a full rebuild of the edited scene");
        double change0 = 0.0;
        for (std::size_t i = 0; i < after.size(); i += 4) change0 += std::abs(after[i] - before[i]);
        QVERIFY2(change0 / double(after.size() / 4) > 0.02, qPrintable(QString("mean change %1").arg(change0 / double(after.size() / 4))));
    }
};

QTEST_APPLESS_MAIN(TestRenderTexturesExt)
#include "test_render_textures_ext.moc"
