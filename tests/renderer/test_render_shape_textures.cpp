// Textures on analytic shapes land where their tessellation puts them: the tessellation is what the
// glTF file carries for other viewers (Blender shows its UVs), so each shape is rendered twice, as
// the shape and as its 512-segment tessellation, with the same textured material, transform and
// camera, and the two images must agree. Perspective camera, 64x64, white environment.
#include "image_stats.h"
#include "test_render_textures_scenes.h"

#include "renderer/gpu_scene/packed_scene.h"
#include "scene/geometry/geometry.h"

#include <QTest>

#include <cmath>
#include <memory>

using namespace glint;
using namespace glint::test;

namespace {

constexpr int kSize = 64;

// 8x8 texels of distinct colours from a fixed hash: a wrong UV shows a wrong colour.
Texels colourTexels() {
    Texels t{8, 8, {}};
    std::uint32_t state = 12345u;
    for (int i = 0; i < 64; ++i) {
        state = state * 1664525u + 1013904223u;
        t.rgba.insert(t.rgba.end(), {std::uint8_t(40 + (state >> 24) % 200), std::uint8_t(40 + (state >> 16) % 200),
                                     std::uint8_t(40 + (state >> 8) % 200), 255});
    }
    return t;
}

// One tangent-space normal everywhere, tilted towards +u (tangent) or -v (bitangent): the shading
// then depends on the tangent frame, so a wrong tangent or handedness changes the picture.
Texels tiltedNormals(bool towardsTangent) {
    const std::uint8_t x = towardsTangent ? 230 : 128, y = towardsTangent ? 128 : 230;
    return {1, 1, {x, y, 200, 255}};
}

Shape shapeOf(ShapeKind kind) {
    Shape shape;
    shape.kind = kind;
    shape.radius = 0.45f;
    shape.height = 0.7f;
    shape.size = kind == ShapeKind::Box ? glm::vec3(0.8f, 0.6f, 0.7f) : glm::vec3(1.0f, 0.0f, 0.9f);
    return shape;
}

// The shape (or its tessellation) turned and squashed so that its world transform matters, seen
// from above and aside; `sun`: a sun as well as a dim sky, for normal maps.
Scene shapeScene(ShapeKind kind, bool tessellated, const Material& material, const Texels& texels, bool sun) {
    Scene scene;
    scene.settings.environment.color = glm::vec3(sun ? 0.2f : 1.0f);
    Material m = material;
    const TextureId texture = addTexture(scene, texels, sampler(Filter::Linear));
    if (sun) m.normalTexture = ref(texture);
    else m.baseColorTexture = ref(texture);
    Shape shape = shapeOf(kind);
    shape.material = scene.materials.add(m);
    Component component = shape;
    if (tessellated) {
        Mesh mesh;
        mesh.primitives.push_back(tessellateShape(shape, 512));
        component = MeshInstance{scene.meshes.add(std::move(mesh))};
    }
    const glm::quat turn = glm::angleAxis(0.5f, glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f)));
    addNode(scene, "shape", component, glm::vec3(0.0f), turn, glm::vec3(1.2f, 0.9f, 1.1f));
    const glm::vec3 eye = kind == ShapeKind::GroundPlane ? glm::vec3(0.4f, 2.0f, 1.5f) : glm::vec3(1.1f, 1.3f, 1.7f);
    addPerspectiveCamera(scene, eye, glm::vec3(0.0f), kind == ShapeKind::GroundPlane ? 0.9f : 0.75f);
    if (sun) addSun(scene, glm::normalize(glm::vec3(-0.6f, -1.0f, -0.3f)), 683.0f);
    return scene;
}

struct Difference {
    double mean = 0.0;    // mean absolute difference over pixels and channels
    double outliers = 0.0; // share of pixels off by more than 0.1 in some channel (silhouettes)
};

Difference difference(const renderer::RenderOutput& a, const renderer::RenderOutput& b) {
    Difference d;
    int off = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            double worst = 0.0;
            for (int c = 0; c < 3; ++c) {
                const double delta = std::abs(double(pixel(a.radiance, kSize, x, y, c)) - double(pixel(b.radiance, kSize, x, y, c)));
                d.mean += delta;
                worst = std::max(worst, delta);
            }
            off += worst > 0.1;
        }
    d.mean /= 3.0 * kSize * kSize;
    d.outliers = double(off) / (kSize * kSize);
    return d;
}

void addKinds() {
    QTest::addColumn<int>("kind");
    QTest::newRow("sphere") << int(ShapeKind::Sphere);
    QTest::newRow("quad") << int(ShapeKind::Quad);
    QTest::newRow("disk") << int(ShapeKind::Disk);
    QTest::newRow("box") << int(ShapeKind::Box);
    QTest::newRow("cylinder") << int(ShapeKind::Cylinder);
    QTest::newRow("ground plane") << int(ShapeKind::GroundPlane);
}

} // namespace

class TestRenderShapeTextures : public QObject {
    Q_OBJECT
    std::unique_ptr<renderer::OfflineRenderer> renderer_;

    Difference shapeAgainstTessellation(ShapeKind kind, const Material& material, const Texels& texels, bool sun, int bounces) {
        const auto shape = renderScene(*renderer_, shapeScene(kind, false, material, texels, sun), kSize, 32, 7, bounces);
        const auto mesh = renderScene(*renderer_, shapeScene(kind, true, material, texels, sun), kSize, 32, 7, bounces);
        const Difference d = difference(shape, mesh);
        qInfo("mean |shape - tessellation| %.4f (image mean %.3f), pixels off by > 0.1: %.2f %%", d.mean,
              channelStats(shape.radiance, 1).mean, 100.0 * d.outliers);
        return d;
    }

private slots:
    void initTestCase() { renderer_ = std::make_unique<renderer::OfflineRenderer>(); }
    void cleanupTestCase() { renderer_.reset(); }

    // Base colour: a Lambert surface under a white sky shows its texels (a convex shape does not see
    // itself), so the two renders differ only by noise and by the tessellation's silhouette: mean
    // difference under 0.01 and at most 3 % of the pixels off by more than 0.1. (Without texture
    // coordinates on shapes every pixel showed the first texel: mean difference ~0.2.)
    void baseColourFollowsTheTessellationsUvs_data() { addKinds(); }
    void baseColourFollowsTheTessellationsUvs() {
        QFETCH(int, kind);
        const Difference d = shapeAgainstTessellation(ShapeKind(kind), lambert(glm::vec3(1.0f)), colourTexels(), false, 1);
        QVERIFY2(d.mean < 0.01, qPrintable(QString::number(d.mean)));
        QVERIFY2(d.outliers < 0.03, qPrintable(QString::number(d.outliers)));
    }

    // Normal maps: a normal tilted along the tangent, then along the bitangent, under a sun. The
    // tangent frame (direction and handedness) must be the tessellation's MikkTSpace frame.
    void normalMapsUseTheTessellationsTangentFrame_data() {
        QTest::addColumn<int>("kind");
        QTest::addColumn<bool>("towardsTangent");
        for (const auto& [name, kind] : {std::pair{"sphere", ShapeKind::Sphere}, {"box", ShapeKind::Box}, {"cylinder", ShapeKind::Cylinder},
                                         {"disk", ShapeKind::Disk}}) {
            QTest::newRow((std::string(name) + " tangent").c_str()) << int(kind) << true;
            QTest::newRow((std::string(name) + " bitangent").c_str()) << int(kind) << false;
        }
    }
    void normalMapsUseTheTessellationsTangentFrame() {
        QFETCH(int, kind);
        QFETCH(bool, towardsTangent);
        const Difference d = shapeAgainstTessellation(ShapeKind(kind), lambert(glm::vec3(0.8f)), tiltedNormals(towardsTangent), true, 0);
        QVERIFY2(d.mean < 0.015, qPrintable(QString::number(d.mean)));
        QVERIFY2(d.outliers < 0.04, qPrintable(QString::number(d.outliers)));
    }

    // An emissive texture on a shape: what the camera sees is factor x texels, as on the mesh, and
    // the shape is not light-sampled with its factor (that would misstate the texels): its sampled
    // power is 0, and BSDF sampling alone finds it.
    void emissiveTextureIsShownAndNotLightSampled() {
        Material m = lambert(glm::vec3(0.0f), glm::vec3(2.0f));
        Scene scene = shapeScene(ShapeKind::Sphere, false, m, colourTexels(), false);
        Material& material = scene.materials.at(scene.at(scene.roots().front()).get<Shape>()->material);
        material.emissiveTexture = material.baseColorTexture;
        QCOMPARE(renderer::packScene(scene, nullptr).shapeEmitterPower, 0.0f);
        Scene tessellated = shapeScene(ShapeKind::Sphere, true, m, colourTexels(), false);
        for (auto& [id, each] : tessellated.materials) each.emissiveTexture = each.baseColorTexture;
        scene.settings.environment.color = tessellated.settings.environment.color = glm::vec3(0.0f);
        const auto a = renderScene(*renderer_, scene, kSize, 16, 3, 1);
        const auto b = renderScene(*renderer_, tessellated, kSize, 16, 3, 1);
        const Difference d = difference(a, b);
        qInfo("emissive: mean difference %.4f, image mean %.3f", d.mean, channelStats(a.radiance, 0).mean);
        QVERIFY(channelStats(a.radiance, 0).maximum > 1.0); // 2 x texels, not clamped
        QVERIFY2(d.mean < 0.02, qPrintable(QString::number(d.mean)));
        QVERIFY2(d.outliers < 0.03, qPrintable(QString::number(d.outliers)));
    }
};

QTEST_APPLESS_MAIN(TestRenderShapeTextures)
#include "test_render_shape_textures.moc"
