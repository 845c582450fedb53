// Lights with extent as emitters that rays find (docs/LIGHTS.md): a finite sun seen in a perfect
// mirror, a sphere lamp seen by the camera, and a glossy plane lit by both, whose mean must equal a
// CPU estimate of the same integral by light sampling alone (through the GLSL's C++ twin).
#include "image_stats.h"
#include "render_scene.h"
#include "scene_builder.h"

#include "renderer/cpu_twin/glsl_twin.h"
#include "renderer/offline_render.h"

#include <QTest>

#include <cmath>
#include <memory>

using namespace glint;
using namespace glint::test;

namespace {

constexpr double kPi = 3.14159265358979;

NodeId addLamp(Scene& scene, LightType type, glm::vec3 position, glm::vec3 shineDirection, float candela, float radius) {
    Light light;
    light.type = type;
    light.intensity = candela;
    light.radius = radius;
    light.innerConeAngle = 0.3f;
    light.outerConeAngle = 0.6f;
    return addNode(scene, "lamp", light, position, lookRotation(shineDirection));
}

// A sun disk's radiance: irradiance (683 lux = 1 W/m^2) over the solid angle of its cone.
double diskRadiance(double irradiance, double diameter) { return irradiance / (2.0 * kPi * (1.0 - std::cos(0.5 * diameter))); }

// Sum over a square perspective image of radiance x solid angle (cosWeight: x cos to the view axis,
// the irradiance on a plane facing the camera), with each pixel's solid angle taken at its centre.
double integrateImage(const std::vector<float>& rgba, int size, float yfov, bool cosWeight) {
    const double tanHalf = std::tan(0.5 * yfov);
    const double step = 2.0 * tanHalf / size;
    double sum = 0.0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const double fx = (x + 0.5) * step - tanHalf;
            const double fy = (y + 0.5) * step - tanHalf;
            const double r2 = 1.0 + fx * fx + fy * fy;
            const double solidAngle = step * step / (r2 * std::sqrt(r2));
            sum += pixel(rgba, size, x, y, 1) * solidAngle * (cosWeight ? 1.0 / std::sqrt(r2) : 1.0);
        }
    return sum;
}

// A perfect white mirror (metallic 1, roughness 0, base colour 1: Fresnel 1 at every angle) as the
// ground, a sun of 683 lux (1 W/m^2) at 40 degrees elevation, and a camera looking along the
// mirrored sun direction from 2 m away.
Scene mirrorUnderSun(float diameter, float yfov) {
    Scene scene;
    addShape(scene, ShapeKind::GroundPlane, scene.materials.add(mirror()), glm::vec3(0.0f));
    const float elevation = glm::radians(40.0f);
    const glm::vec3 shine(std::cos(elevation), -std::sin(elevation), 0.0f);
    addSun(scene, shine, 683.0f, diameter);
    const glm::vec3 reflected(shine.x, -shine.y, shine.z); // the mirrored sun rays, leaving the ground
    addPerspectiveCamera(scene, 2.0f * reflected, glm::vec3(0.0f), yfov);
    return scene;
}

// The CPU side: SurfaceMaterial of the glTF material the GPU tests use.
twin::SurfaceMaterial twinMaterial(float metallic, float roughness, glm::vec3 baseColor) {
    twin::SurfaceMaterial m = twin::defaultSurfaceMaterial();
    m.metallic = metallic;
    m.roughness = roughness;
    m.baseColor = baseColor;
    m.specularFactor = metallic > 0.0f ? 1.0f : 0.0f;
    return m;
}

// Light-sampling estimate of radiance reflected towards +Z (wo) by a horizontal surface at the
// origin from a cone of directions around `axis` of uniform radiance L: mean of f cos L / pdf.
double coneReflection(const twin::SurfaceMaterial& m, glm::vec3 axis, float oneMinusCos, double radiance, int samples) {
    const twin::Frame cone = twin::frameFromNormal(glm::normalize(axis));
    const float pdf = twin::conePdfFromOneMinusCos(oneMinusCos);
    twin::Rng rng = twin::rngStart(glm::uvec2(5u, 9u), 0u, 3u);
    double sum = 0.0;
    for (int i = 0; i < samples; ++i) {
        const glm::vec3 wi = twin::worldFromLocal(cone, twin::uniformCone(twin::rand2(rng), 1.0f - oneMinusCos));
        float bsdfPdf;
        // World up is the shading normal, so world and local frames agree.
        sum += double(twin::bsdfEval(m, glm::vec3(0.0f, 0.0f, 1.0f), glm::vec3(wi.x, wi.z, wi.y), bsdfPdf).y) * radiance / pdf;
    }
    return sum / samples;
}

} // namespace

class TestRenderLightVisibility : public QObject {
    Q_OBJECT
    std::unique_ptr<renderer::OfflineRenderer> renderer_;

private slots:
    void initTestCase() { renderer_ = std::make_unique<renderer::OfflineRenderer>(); }
    void cleanupTestCase() { renderer_.reset(); }

    // 8x8, 4 spp, seed 30, 1 bounce. A 0.1 rad sun seen in the mirror through a 0.02 rad field of
    // view: every pixel shows the disk's radiance 1 / (2 pi (1 - cos 0.05)) = 127.35 (within 0.1 %).
    // A delta sun is seen in no mirror.
    void mirrorShowsSunDiskRadiance() {
        const double disk = diskRadiance(1.0, 0.1);
        const ChannelStats seen = channelStats(renderScene(*renderer_, mirrorUnderSun(0.1f, 0.02f), 8, 4, 30, 1).radiance, 1);
        qInfo("mirrored disk %.4f .. %.4f, expected %.4f", seen.minimum, seen.maximum, disk);
        QVERIFY2(std::abs(seen.minimum - disk) < 1e-3 * disk && std::abs(seen.maximum - disk) < 1e-3 * disk,
                 qPrintable(QString("mirrored disk %1 .. %2 vs %3").arg(seen.minimum).arg(seen.maximum).arg(disk)));
        QCOMPARE(channelStats(renderScene(*renderer_, mirrorUnderSun(0.0f, 0.02f), 8, 4, 30, 1).radiance, 1).maximum, 0.0);
    }

    // 32x32, 64 spp, seed 31, 1 bounce. The whole mirrored disk (0.1 rad) inside a 0.3 rad view: the
    // image's radiance x solid angle sums to the disk's L x Omega = the sun's irradiance, 1 W/m^2
    // (within 1 %; the disk's edge pixels are estimated by the pixel jitter).
    void mirrorReflectsSunEnergy() {
        const float yfov = 0.3f;
        const auto image = renderScene(*renderer_, mirrorUnderSun(0.1f, yfov), 32, 64, 31, 1).radiance;
        const double energy = integrateImage(image, 32, yfov, false);
        qInfo("reflected L x Omega %.5f, expected 1", energy);
        QVERIFY2(std::abs(energy - 1.0) < 0.01, qPrintable(QString("reflected L x Omega %1 vs 1").arg(energy)));
    }

    // 8x8, 1 spp, seed 32, 0 bounces. A lamp of radius 0.25 m and 683 cd (1 W/sr) seen from 3 m
    // through a 0.02 rad view: radiance I / (pi r^2) = 5.093 (within 0.1 %). A spot lamp shining
    // 0.45 rad away from the camera, between its inner (0.3) and outer (0.6) cone angles: that times
    // the spot falloff ((cos 0.45 - cos 0.6) / (cos 0.3 - cos 0.6))^2.
    // In a perfect white mirror (1 bounce) the point lamp shows the same radiance.
    void lampSphereShowsItsRadiance_data() {
        QTest::addColumn<bool>("spot");
        QTest::addColumn<bool>("mirrored");
        QTest::newRow("point") << false << false;
        QTest::newRow("spot") << true << false;
        QTest::newRow("point in a mirror") << false << true;
    }
    void lampSphereShowsItsRadiance() {
        QFETCH(bool, spot);
        QFETCH(bool, mirrored);
        Scene scene;
        const float away = spot ? 0.45f : 0.0f;
        const glm::vec3 shine(std::sin(away), 0.0f, std::cos(away)); // the camera is along +Z
        addLamp(scene, spot ? LightType::Spot : LightType::Point, glm::vec3(0.0f), shine, 683.0f, 0.25f);
        if (mirrored) {
            // The mirror y = -1; the camera looks at the lamp's image at (0, -2, 0).
            addShape(scene, ShapeKind::GroundPlane, scene.materials.add(mirror()), {0.0f, -1.0f, 0.0f});
            addPerspectiveCamera(scene, {0.0f, 1.0f, 2.0f}, {0.0f, -2.0f, 0.0f}, 0.02f);
        } else {
            addPerspectiveCamera(scene, {0.0f, 0.0f, 3.0f}, glm::vec3(0.0f), 0.02f);
        }
        double expected = 1.0 / (kPi * 0.25 * 0.25);
        if (spot) expected *= std::pow((std::cos(0.45) - std::cos(0.6)) / (std::cos(0.3) - std::cos(0.6)), 2.0);
        const ChannelStats seen = channelStats(renderScene(*renderer_, scene, 8, 1, 32, mirrored ? 1 : 0).radiance, 1);
        qInfo("lamp %.5f .. %.5f, expected %.5f", seen.minimum, seen.maximum, expected);
        QVERIFY2(std::abs(seen.minimum - expected) < 1e-3 * expected && std::abs(seen.maximum - expected) < 1e-3 * expected,
                 qPrintable(QString("lamp %1 .. %2 vs %3").arg(seen.minimum).arg(seen.maximum).arg(expected)));
    }

    // 32x32, 64 spp, seed 33, 0 bounces. The same point lamp filling part of a 0.4 rad view from 2 m:
    // radiance x cos x solid angle sums to the irradiance on a plane facing it, I / d^2 = 0.25
    // (within 1 %), as the light sampling's sphere gives (test_render_light_shapes).
    void lampSphereImageGivesIrradiance() {
        Scene scene;
        addLamp(scene, LightType::Point, glm::vec3(0.0f), {0.0f, 0.0f, 1.0f}, 683.0f, 0.25f);
        addPerspectiveCamera(scene, {0.0f, 0.0f, 2.0f}, glm::vec3(0.0f), 0.4f);
        const double irradiance = integrateImage(renderScene(*renderer_, scene, 32, 64, 33, 0).radiance, 32, 0.4f, true);
        qInfo("lamp image irradiance %.5f, expected 0.25", irradiance);
        QVERIFY2(std::abs(irradiance - 0.25) < 0.01 * 0.25, qPrintable(QString("%1 vs 0.25").arg(irradiance)));
    }

    // 16x16, 4 spp, seed 35, 0 bounces: an orthographic view down on a white Lambert ground under a
    // delta sun of 683 lux straight down, with a dark lamp sphere (0 cd, r 0.5 m) 1 m up. The lamp
    // blocks the sun's shadow rays: the ground under it is black, while a lamp never shadows its own
    // light (test_render_light_shapes: its irradiance is I / d^2 within 1 %). The view is 0.6 m wide:
    // all of it in the shadow; beside the lamp, all of it lit with radiance 1/pi (within 0.1 %).
    void lampShadowsOtherLights() {
        Scene scene;
        addShape(scene, ShapeKind::GroundPlane, scene.materials.add(lambert(glm::vec3(1.0f))), glm::vec3(0.0f));
        addSun(scene, {0.0f, -1.0f, 0.0f}, 683.0f);
        addLamp(scene, LightType::Point, {0.0f, 1.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 0.0f, 0.5f);
        addOrthographicCamera(scene, {0.0f, 0.1f, 0.0f}, {0.0f, -1.0f, 0.0f}, 0.3f);
        const ChannelStats shadow = channelStats(renderScene(*renderer_, scene, 16, 4, 35, 0).radiance, 1);
        QCOMPARE(shadow.maximum, 0.0);
        scene.settings.activeCamera = addOrthographicCamera(scene, {2.0f, 0.1f, 0.0f}, {0.0f, -1.0f, 0.0f}, 0.3f);
        const ChannelStats open = channelStats(renderScene(*renderer_, scene, 16, 4, 35, 0).radiance, 1);
        QVERIFY2(std::abs(open.minimum - 1.0 / kPi) < 1e-3 && std::abs(open.maximum - 1.0 / kPi) < 1e-3,
                 qPrintable(QString("beside the lamp %1 .. %2 vs 1/pi").arg(open.minimum).arg(open.maximum)));
    }

    // 32x32, 32 spp, seed 34, 0 bounces: a 1 cm orthographic view down on a plane lit by a sphere lamp
    // (683 cd, r 0.3 m, 2 m straight up) and a 0.1 rad sun of 683 lux tilted 0.3 rad, whose light
    // samples and BSDF samples each carry a share under MIS. The image mean must equal the CPU's
    // light-sampling estimate (2^20 samples per light through the twin's bsdfEval) within 4 standard
    // errors of the mean over pixels plus 0.5 %.
    void glossyPlaneMatchesLightSampling_data() {
        QTest::addColumn<float>("metallic");
        QTest::addColumn<float>("roughness");
        QTest::newRow("glossy metal, roughness 0.3") << 1.0f << 0.3f;
        QTest::newRow("rough metal, roughness 0.6") << 1.0f << 0.6f;
        QTest::newRow("lambert") << 0.0f << 1.0f;
    }
    void glossyPlaneMatchesLightSampling() {
        QFETCH(float, metallic);
        QFETCH(float, roughness);
        const glm::vec3 base(0.9f);
        Material material = metallic > 0.0f ? mirror() : lambert(base);
        material.baseColorFactor = glm::vec4(base, 1.0f);
        material.roughnessFactor = roughness;
        Scene scene;
        addShape(scene, ShapeKind::GroundPlane, scene.materials.add(material), glm::vec3(0.0f));
        addLamp(scene, LightType::Point, {0.0f, 2.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 683.0f, 0.3f);
        const glm::vec3 towardsSun(std::sin(0.3f), std::cos(0.3f), 0.0f); // clear of the lamp's 0.15 rad cone
        addSun(scene, -towardsSun, 683.0f, 0.1f);
        addOrthographicCamera(scene, {0.0f, 0.1f, 0.0f}, {0.0f, -1.0f, 0.0f}, 0.005f);
        const ChannelStats image = channelStats(renderScene(*renderer_, scene, 32, 32, 34, 0).radiance, 1);

        const twin::SurfaceMaterial m = twinMaterial(metallic, roughness, base);
        const float lampCone = twin::sphereConeOneMinusCos(0.3f, 4.0f);
        const double lampRadiance = 1.0 / (kPi * 0.09);
        const double expected = coneReflection(m, {0.0f, 1.0f, 0.0f}, lampCone, lampRadiance, 1 << 20) +
                                coneReflection(m, towardsSun, float(1.0 - std::cos(0.05)), diskRadiance(1.0, 0.1), 1 << 20);
        const double standardError = image.stddev / std::sqrt(32.0 * 32.0);
        const double tolerance = 4.0 * standardError + 0.005 * expected;
        qInfo("image mean %.5f +- %.5f, light sampling %.5f", image.mean, standardError, expected);
        QVERIFY2(std::abs(image.mean - expected) < tolerance,
                 qPrintable(QString("image %1 +- %2 vs light sampling %3").arg(image.mean).arg(standardError).arg(expected)));
    }
};

QTEST_APPLESS_MAIN(TestRenderLightVisibility)
#include "test_render_light_visibility.moc"
