// Area lights and emissive shapes as lights (docs/LIGHTS.md): irradiance under a rectangle and a
// disk against their closed forms, light sampling, BSDF sampling and MIS agreeing, an area
// rectangle against an emissive mesh quad in a closed room, and a many-triangle emissive sphere
// mesh against the analytic emissive sphere. Scenes are built in code; each test states its size,
// spp, seed and tolerance. Statistical comparisons use the renderer's per-pixel sample variance:
// the standard error of an image mean is sqrt(sum of variances / spp) / pixels.
#include "image_stats.h"
#include "mesh_builder.h"
#include "render_scene.h"
#include "scene_builder.h"

#include "renderer/offline_render.h"
#include "scene/geometry/geometry.h"
#include "scene/io/scene_io.h"

#include <QTest>

#include <cmath>
#include <memory>

using namespace glint;
using namespace glint::test;

namespace {

constexpr double kPi = 3.14159265358979;

// An area light node at `position` whose emitting face looks along `direction`.
NodeId addAreaLight(Scene& scene, AreaShape shape, float watts, glm::vec2 size, float radius, glm::vec3 position,
                    glm::vec3 direction = {0.0f, -1.0f, 0.0f}) {
    Light light;
    light.type = LightType::Area;
    light.areaShape = shape;
    light.intensity = watts;
    light.size = size;
    light.radius = radius;
    const glm::vec3 up = std::abs(glm::normalize(direction).y) > 0.99f ? glm::vec3(0.0f, 0.0f, -1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    return addNode(scene, "area", light, position, lookRotation(direction, up));
}

// The view factor from a point to a parallel rectangle a x b at distance h with one corner straight
// above the point (the standard closed form): irradiance = pi L F for a Lambertian emitter of radiance L.
double cornerViewFactor(double a, double b, double h) {
    const double x = a / h, y = b / h;
    const double sx = std::sqrt(1.0 + x * x), sy = std::sqrt(1.0 + y * y);
    return (x / sx * std::atan(y / sx) + y / sy * std::atan(x / sy)) / (2.0 * kPi);
}

struct Mean {
    double value = 0.0;
    double standardError = 0.0;
};

// Mean of channel c over the image, and its standard error from the per-pixel sample variance.
Mean imageMean(const renderer::RenderOutput& out, int spp, int c = 1) {
    const std::size_t pixels = out.variance.size() / 3;
    double sum = 0.0, variance = 0.0;
    for (std::size_t i = 0; i < pixels; ++i) {
        sum += out.radiance[i * 4 + std::size_t(c)];
        variance += out.variance[i * 3 + std::size_t(c)];
    }
    return {sum / double(pixels), std::sqrt(variance / spp) / double(pixels)};
}

// The mean over pixels of each pixel's standard error at `spp` (the noise one sees), channel c.
double meanPixelError(const renderer::RenderOutput& out, int spp, int c = 1) {
    const std::size_t pixels = out.variance.size() / 3;
    double sum = 0.0;
    for (std::size_t i = 0; i < pixels; ++i) sum += std::sqrt(out.variance[i * 3 + std::size_t(c)] / spp);
    return sum / double(pixels);
}

double zScore(Mean a, Mean b) { return std::abs(a.value - b.value) / std::sqrt(a.standardError * a.standardError + b.standardError * b.standardError); }

// A closed 1 m room (x and z in [-0.5, 0.5], y in [0, 1]) of analytic quads: white floor, ceiling,
// back and front walls, a red left and a green right wall; a camera inside looks at the back wall.
Scene room() {
    Scene scene;
    const MaterialId white = scene.materials.add(lambert(glm::vec3(0.73f)));
    const MaterialId red = scene.materials.add(lambert({0.63f, 0.065f, 0.05f}));
    const MaterialId green = scene.materials.add(lambert({0.14f, 0.45f, 0.09f}));
    const glm::quat aboutZ = glm::angleAxis(0.5f * float(kPi), glm::vec3(0.0f, 0.0f, 1.0f));
    const glm::quat aboutX = glm::angleAxis(0.5f * float(kPi), glm::vec3(1.0f, 0.0f, 0.0f));
    addShape(scene, ShapeKind::Quad, white, {0.0f, 0.0f, 0.0f}, 0.5f, glm::vec3(1.0f));
    addShape(scene, ShapeKind::Quad, white, {0.0f, 1.0f, 0.0f}, 0.5f, glm::vec3(1.0f));
    addShape(scene, ShapeKind::Quad, red, {-0.5f, 0.5f, 0.0f}, 0.5f, glm::vec3(1.0f), aboutZ);
    addShape(scene, ShapeKind::Quad, green, {0.5f, 0.5f, 0.0f}, 0.5f, glm::vec3(1.0f), aboutZ);
    addShape(scene, ShapeKind::Quad, white, {0.0f, 0.5f, -0.5f}, 0.5f, glm::vec3(1.0f), aboutX);
    addShape(scene, ShapeKind::Quad, white, {0.0f, 0.5f, 0.5f}, 0.5f, glm::vec3(1.0f), aboutX);
    addPerspectiveCamera(scene, {0.0f, 0.5f, 0.45f}, {0.0f, 0.45f, -0.5f}, 1.2f);
    return scene;
}

// Total area of a mesh's triangles.
double meshArea(const Primitive& p) {
    double area = 0.0;
    for (std::size_t t = 0; t + 2 < p.indices.size(); t += 3) {
        const glm::vec3 a = p.positions[p.indices[t]], b = p.positions[p.indices[t + 1]], c = p.positions[p.indices[t + 2]];
        area += 0.5 * double(glm::length(glm::cross(b - a, c - a)));
    }
    return area;
}

} // namespace

class TestRenderAreaLights : public QObject {
    Q_OBJECT
    std::unique_ptr<renderer::OfflineRenderer> renderer_;

    renderer::RenderOutput render(const Scene& scene, int size, int spp, std::uint32_t seed, int bounces,
                                  renderer::AreaLightStrategy strategy = renderer::AreaLightStrategy::Mis) {
        renderer::RenderRequest request = stillRequest(size, spp, seed, bounces);
        request.tonemapper = Tonemapper::None;
        request.areaLightStrategy = strategy;
        return renderer_->render(scene, request);
    }

    // A white Lambert ground (albedo 1) seen straight down through a 2 mm orthographic window at
    // `at`, under one area light 1 m up facing down; 0 bounces. Returns the image's mean, which is
    // the radiance the ground reflects, E / pi.
    Mean groundUnder(AreaShape shape, glm::vec2 size, glm::vec3 at, int spp, std::uint32_t seed) {
        Scene scene;
        const MaterialId white = scene.materials.add(lambert(glm::vec3(1.0f)));
        addShape(scene, ShapeKind::GroundPlane, white, glm::vec3(0.0f));
        addAreaLight(scene, shape, 10.0f, size, 0.0f, {0.0f, 1.0f, 0.0f});
        addOrthographicCamera(scene, at + glm::vec3(0.0f, 0.5f, 0.0f), {0.0f, -1.0f, 0.0f}, 0.001f);
        return imageMean(render(scene, 32, spp, seed, 0), spp);
    }

private slots:
    void initTestCase() { renderer_ = std::make_unique<renderer::OfflineRenderer>(); }
    void cleanupTestCase() { renderer_.reset(); }

    // 32x32, 64 spp, seeds 1 and 2. A 10 W rectangle 1 m x 0.5 m (radiance 10 / (pi 0.5)) 1 m over
    // the ground, the point straight under its centre and a point 0.3 m off along its long side: the
    // reflected radiance L F (albedo 1; F the view factor, four corner rectangles each) within 0.5 %.
    void rectangleIrradianceClosedForm() {
        const double radiance = 10.0 / (kPi * 0.5);
        const double centre = radiance * 4.0 * cornerViewFactor(0.5, 0.25, 1.0);
        const double offset = radiance * 2.0 * (cornerViewFactor(0.8, 0.25, 1.0) + cornerViewFactor(0.2, 0.25, 1.0));
        const Mean a = groundUnder(AreaShape::Rectangle, {1.0f, 0.5f}, glm::vec3(0.0f), 64, 1);
        const Mean b = groundUnder(AreaShape::Rectangle, {1.0f, 0.5f}, {0.3f, 0.0f, 0.0f}, 64, 2);
        qInfo("rectangle: centre %.6f vs %.6f (%+.3f %%), offset %.6f vs %.6f (%+.3f %%)", a.value, centre,
              100.0 * (a.value / centre - 1.0), b.value, offset, 100.0 * (b.value / offset - 1.0));
        QVERIFY2(std::abs(a.value / centre - 1.0) < 0.005, qPrintable(QString("centre %1 vs %2").arg(a.value).arg(centre)));
        QVERIFY2(std::abs(b.value / offset - 1.0) < 0.005, qPrintable(QString("offset %1 vs %2").arg(b.value).arg(offset)));
    }

    // 32x32, 64 spp, seed 3. A 10 W disk of diameter 0.8 m 1 m over the ground: under its centre
    // L F, F = R^2 / (h^2 + R^2), within 0.5 %.
    void diskIrradianceClosedForm() {
        const double r = 0.4, area = kPi * r * r;
        const double expected = 10.0 / (kPi * area) * r * r / (1.0 + r * r);
        const Mean m = groundUnder(AreaShape::Disk, {0.8f, 0.8f}, glm::vec3(0.0f), 64, 3);
        qInfo("disk: %.6f vs %.6f (%+.3f %%), standard error %.3f %%", m.value, expected, 100.0 * (m.value / expected - 1.0),
              100.0 * m.standardError / expected);
        QVERIFY2(std::abs(m.value / expected - 1.0) < 0.005, qPrintable(QString("%1 vs %2").arg(m.value).arg(expected)));
    }

    // 32x32, 256 spp, seeds 4-6, 3 bounces. The room lit by an area rectangle, an area disk, an area
    // sphere and an emissive analytic box, rendered by light sampling alone, BSDF sampling alone and
    // MIS: the three image means agree within 4 standard errors of their difference (and 1 %).
    void strategiesAgree() {
        Scene scene = room();
        addAreaLight(scene, AreaShape::Rectangle, 3.0f, {0.3f, 0.2f}, 0.0f, {-0.2f, 0.99f, -0.1f});
        addAreaLight(scene, AreaShape::Disk, 3.0f, {0.3f, 0.3f}, 0.0f, {0.2f, 0.99f, -0.2f});
        addAreaLight(scene, AreaShape::Sphere, 3.0f, {1.0f, 1.0f}, 0.08f, {0.15f, 0.6f, -0.2f});
        const MaterialId glow = scene.materials.add(lambert(glm::vec3(0.5f), glm::vec3(2.0f, 1.5f, 1.0f)));
        addShape(scene, ShapeKind::Box, glow, {-0.25f, 0.1f, -0.25f}, 0.5f, glm::vec3(0.15f));
        const int spp = 256;
        const Mean mis = imageMean(render(scene, 32, spp, 4, 3), spp);
        const Mean light = imageMean(render(scene, 32, spp, 5, 3, renderer::AreaLightStrategy::LightOnly), spp);
        const Mean bsdf = imageMean(render(scene, 32, spp, 6, 3, renderer::AreaLightStrategy::BsdfOnly), spp);
        qInfo("MIS %.5f +- %.5f, light only %.5f +- %.5f, BSDF only %.5f +- %.5f", mis.value, mis.standardError, light.value,
              light.standardError, bsdf.value, bsdf.standardError);
        for (const auto& [name, other] : {std::pair{"light only", light}, std::pair{"BSDF only", bsdf}}) {
            QVERIFY2(zScore(mis, other) < 4.0 && std::abs(other.value / mis.value - 1.0) < 0.01,
                     qPrintable(QString("MIS %1 vs %2 %3, z %4").arg(mis.value).arg(name).arg(other.value).arg(zScore(mis, other))));
        }
        QVERIFY2(zScore(light, bsdf) < 4.0, qPrintable(QString("light only %1 vs BSDF only %2").arg(light.value).arg(bsdf.value)));
        // Light sampling is what makes area lights converge: MIS is far less noisy than BSDF sampling alone.
        QVERIFY2(mis.standardError < 0.5 * bsdf.standardError,
                 qPrintable(QString("standard errors: MIS %1, BSDF only %2").arg(mis.standardError).arg(bsdf.standardError)));
    }

    // 32x32, 256 spp, seeds 7 and 8, 4 bounces. The room lit by a 0.25 m square area light of 2 W
    // just under the ceiling, against the same room lit by a single-sided emissive mesh quad of the
    // same size, place and radiance (2 / (pi 0.0625)): the mean brightness agrees within 4 standard
    // errors and 1 %.
    void areaRectangleMatchesEmissiveQuad() {
        const int spp = 256;
        Scene area = room();
        addAreaLight(area, AreaShape::Rectangle, 2.0f, {0.25f, 0.25f}, 0.0f, {0.0f, 0.99f, 0.0f});
        Scene mesh = room();
        Material emitter = lambert(glm::vec3(0.0f), glm::vec3(float(2.0 / (kPi * 0.0625))));
        emitter.doubleSided = false;
        const MeshId quad = mesh.meshes.add(quadMesh(0.25f, mesh.materials.add(emitter)));
        addNode(mesh, "emitter", MeshInstance{quad}, {0.0f, 0.99f, 0.0f}, glm::angleAxis(float(kPi), glm::vec3(1.0f, 0.0f, 0.0f)));
        const Mean a = imageMean(render(area, 32, spp, 7, 4), spp);
        const Mean b = imageMean(render(mesh, 32, spp, 8, 4), spp);
        qInfo("area rectangle %.5f +- %.5f, emissive quad %.5f +- %.5f", a.value, a.standardError, b.value, b.standardError);
        QVERIFY2(zScore(a, b) < 4.0 && std::abs(a.value / b.value - 1.0) < 0.01,
                 qPrintable(QString("area %1 vs mesh %2, z %3").arg(a.value).arg(b.value).arg(zScore(a, b))));
    }

    // 32x32, 512 spp, seeds 9, 10 and 13, 16 bounces. The bundled Cornell box (0.55 m) lit by a
    // small emissive sphere (radius 0.04 m, 0.1 m under the ceiling) instead of its quad: as an
    // analytic shape and as its 2208-triangle mesh (48 segments, 24 rings, single-sided), the
    // mesh's emission scaled by the sphere's area over the mesh's so that both send out the same
    // flux. The mesh under MIS agrees with the analytic sphere (4 standard errors and 1 %) and with
    // itself found by BSDF sampling alone, which traces no shadow ray to the emitter and so cannot
    // lose light to shadow-ray offsets (4 standard errors and 2 %). Before shadow rays ended at a
    // point moved off the emitter (integrator.glsl shadowRay) they were shortened by 1e-4 of their
    // length from an origin moved off the receiver, and reached the emitter itself within ~0.15 m
    // of it: the mesh room was 10 % too dark here.
    void emissiveSphereMeshMatchesAnalyticSphere() {
        const int spp = 512;
        const float radius = 0.04f;
        const glm::vec3 at(0.278f, 0.45f, 0.28f);
        const glm::vec3 emission(200.0f);
        const auto box = [] {
            Scene scene = loadScene(GLINT_RESOURCES_DIR "/scenes/cornell_box/cornell_box.gltf").scene;
            scene.setComponent(*scene.findByName("light"), Component{});
            return scene;
        };
        Scene analytic = box();
        addShape(analytic, ShapeKind::Sphere, analytic.materials.add(lambert(glm::vec3(0.0f), emission)), at, radius);
        Scene mesh = box();
        Shape sphere;
        sphere.kind = ShapeKind::Sphere;
        sphere.radius = radius;
        Primitive surface = tessellateShape(sphere, 48);
        QCOMPARE(surface.triangleCount(), std::size_t(2208));
        const double areaRatio = 4.0 * kPi * radius * radius / meshArea(surface);
        Material emitter = lambert(glm::vec3(0.0f), emission * float(areaRatio));
        emitter.doubleSided = false;
        surface.material = mesh.materials.add(emitter);
        Mesh sphereMesh;
        sphereMesh.primitives.push_back(std::move(surface));
        addNode(mesh, "emitter", MeshInstance{mesh.meshes.add(std::move(sphereMesh))}, at);
        const auto analyticOut = render(analytic, 32, spp, 9, 16);
        const auto meshOut = render(mesh, 32, spp, 10, 16);
        const auto bsdfOut = render(mesh, 32, spp, 13, 16, renderer::AreaLightStrategy::BsdfOnly);
        const Mean a = imageMean(analyticOut, spp);
        const Mean b = imageMean(meshOut, spp);
        const Mean c = imageMean(bsdfOut, spp);
        qInfo("analytic sphere %.4f +- %.4f, 2208-triangle mesh %.4f +- %.4f (%+.2f %%), mesh by BSDF sampling alone %.4f +- %.4f "
              "(%+.2f %%)", a.value, a.standardError, b.value, b.standardError, 100.0 * (b.value / a.value - 1.0), c.value,
              c.standardError, 100.0 * (b.value / c.value - 1.0));
        QVERIFY2(zScore(a, b) < 4.0 && std::abs(b.value / a.value - 1.0) < 0.01,
                 qPrintable(QString("analytic %1 vs mesh %2, z %3").arg(a.value).arg(b.value).arg(zScore(a, b))));
        QVERIFY2(zScore(b, c) < 4.0 && std::abs(b.value / c.value - 1.0) < 0.02,
                 qPrintable(QString("mesh %1 vs BSDF sampling alone %2, z %3").arg(b.value).arg(c.value).arg(zScore(b, c))));
    }

    // 32x32, 64 spp, seeds 11 and 12, 16 bounces. The same small analytic emissive sphere: with
    // next-event estimation (MIS) the pixels' noise is a fraction of BSDF sampling's alone, which
    // is how such a shape rendered before it was light-sampled. Measured: about 1/10 (docs/LIGHTS.md).
    void shapeNextEventEstimationCutsNoise() {
        const int spp = 64;
        Scene scene = room();
        addShape(scene, ShapeKind::Sphere, scene.materials.add(lambert(glm::vec3(0.0f), glm::vec3(20.0f))), {0.0f, 0.75f, -0.1f}, 0.04f);
        const double mis = meanPixelError(render(scene, 32, spp, 11, 16), spp);
        const double bsdf = meanPixelError(render(scene, 32, spp, 12, 16, renderer::AreaLightStrategy::BsdfOnly), spp);
        qInfo("pixel noise at 64 spp: MIS %.5f, BSDF only %.5f (%.1fx)", mis, bsdf, bsdf / mis);
        QVERIFY2(mis < 0.25 * bsdf, qPrintable(QString("MIS %1, BSDF only %2").arg(mis).arg(bsdf)));
    }
};

QTEST_APPLESS_MAIN(TestRenderAreaLights)
#include "test_render_area_lights.moc"
