// Known-answer renders of participating media (docs/MEDIA.md): the fog's transmittance, homogeneous
// and falling with height; the unscattered light through a scattering volume with per-channel
// extinction; white furnaces filled with albedo-1 fog and with an albedo-1 volume; a spot light's
// beam in fog against a single-scattering integral computed here. Each test states its size, spp,
// seed and tolerance; tolerances are in standard errors of the mean, pooled where pixels share a
// distribution. Scenes are built in code.
#include "image_stats.h"
#include "render_scene.h"
#include "scene_builder.h"

#include "renderer/offline_render.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

using namespace glint;
using namespace glint::test;

namespace {

// A volume boundary that neither reflects nor bends (IOR 1): only the medium inside shows.
Material scatteringVolume(glm::vec3 attenuationColor, float attenuationDistance, glm::vec3 albedo, float g) {
    Material m = glass(1.0f, 1.0f);
    m.attenuationColor = attenuationColor;
    m.attenuationDistance = attenuationDistance;
    m.scatterColor = albedo;
    m.scatterAnisotropy = g;
    return m;
}

// Mean and standard error of channel c over the pixels `inside` selects.
struct Estimate {
    double mean = 0.0;
    double sigma = 0.0;
    int pixels = 0;
};

Estimate estimate(const renderer::RenderOutput& out, int size, int spp, int c, const std::function<bool(int, int)>& inside) {
    Estimate e;
    double variance = 0.0;
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            if (!inside(x, y)) continue;
            e.mean += pixel(out.radiance, size, x, y, c);
            variance += out.variance[std::size_t(y * size + x) * 3 + std::size_t(c)];
            ++e.pixels;
        }
    }
    e.mean /= e.pixels;
    e.sigma = std::sqrt(variance / e.pixels / spp / e.pixels);
    return e;
}

QString describe(const Estimate& e, double expected) {
    return QString("mean %1, expected %2, sigma %3 over %4 pixels").arg(e.mean).arg(expected).arg(e.sigma).arg(e.pixels);
}

// The Henyey-Greenstein phase function, written out here independently of the shader's.
double phase(double cosTheta, double g) { return (1.0 - g * g) / (4.0 * M_PI * std::pow(1.0 + g * g - 2.0 * g * cosTheta, 1.5)); }

// The expected image of an orthographic view (rows top-down) centred on `centre` with the camera's
// `halfHeight`: radiance(x, y), a function of the point on the view plane, averaged over n x n
// points per pixel.
std::vector<double> expectedImage(int size, glm::dvec2 centre, double halfHeight, int n,
                                  const std::function<double(double, double)>& radiance) {
    std::vector<double> image(std::size_t(size * size));
    const double pixelSize = 2.0 * halfHeight / size;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            for (int sy = 0; sy < n; ++sy)
                for (int sx = 0; sx < n; ++sx)
                    image[std::size_t(y * size + x)] += radiance(centre.x - halfHeight + (x + (sx + 0.5) / n) * pixelSize,
                                                                 centre.y + halfHeight - (y + (sy + 0.5) / n) * pixelSize) / (n * n);
    return image;
}

// The red channel against `expected`: each pixel within 4.5 standard errors + 1 % of the expected peak, and the
// image's sum within 1 %.
void compareWithExpected(const renderer::RenderOutput& out, int size, int spp, const std::vector<double>& expected) {
    const double peak = *std::max_element(expected.begin(), expected.end());
    QVERIFY2(peak > 0.01, qPrintable(QString("expected peak %1: nothing to compare").arg(peak)));
    double sumRendered = 0.0, sumExpected = 0.0;
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const double value = pixel(out.radiance, size, x, y, 0);
            const double reference = expected[std::size_t(y * size + x)];
            const double se = std::sqrt(out.variance[std::size_t(y * size + x) * 3] / spp);
            sumRendered += value;
            sumExpected += reference;
            QVERIFY2(std::abs(value - reference) < 4.5 * se + 0.01 * peak,
                     qPrintable(QString("pixel %1,%2: %3, expected %4, standard error %5").arg(x).arg(y).arg(value).arg(reference).arg(se)));
        }
    }
    QVERIFY2(std::abs(sumRendered / sumExpected - 1.0) < 0.01, qPrintable(QString("image sum %1, expected %2").arg(sumRendered).arg(sumExpected)));
}

} // namespace

class TestRenderMedia : public QObject {
    Q_OBJECT
    std::unique_ptr<renderer::OfflineRenderer> renderer_;

    renderer::RenderOutput render(const Scene& scene, int size, int spp, std::uint32_t seed, int bounces) {
        renderer::RenderRequest request = test::stillRequest(size, spp, seed, bounces);
        request.tonemapper = Tonemapper::None;
        return renderer_->render(scene, request);
    }

    // A closed sphere (radius 5) of Lambert albedo 0.5 emitting 0.5: radiance 1 everywhere inside.
    static Scene furnaceRoom() {
        Scene scene;
        const MaterialId wall = scene.materials.add(lambert(glm::vec3(0.5f), glm::vec3(0.5f)));
        addShape(scene, ShapeKind::Sphere, wall, glm::vec3(0.0f), 5.0f);
        return scene;
    }

private slots:
    void initTestCase() { renderer_ = std::make_unique<renderer::OfflineRenderer>(); }
    void cleanupTestCase() { renderer_.reset(); }

    // 32x32, 64 spp, seed 1, 0 bounces. The camera at the centre of an emitting sphere (radius 50,
    // radiance 1) in a fog of density 0.02 that only absorbs (albedo 0): every ray crosses 50 m, so
    // the image is exp(-1) on average, within 4 standard errors of the whole image's mean.
    void homogeneousFogTransmitsExpOfDepth() {
        Scene scene;
        addShape(scene, ShapeKind::Sphere, scene.materials.add(lambert(glm::vec3(0.0f), glm::vec3(1.0f))), glm::vec3(0.0f), 50.0f);
        addPerspectiveCamera(scene, glm::vec3(0.0f), {0.3f, 0.2f, -1.0f}, 1.2f);
        scene.settings.fog = {.density = 0.02f, .color = glm::vec3(0.0f)};
        const int size = 32, spp = 64;
        const auto out = render(scene, size, spp, 1, 0);
        const double expected = std::exp(-1.0);
        const Estimate e = estimate(out, size, spp, 1, [](int, int) { return true; });
        QVERIFY2(e.sigma < 0.003, qPrintable(describe(e, expected)));
        QVERIFY2(std::abs(e.mean - expected) < 4.0 * e.sigma, qPrintable(describe(e, expected)));
    }

    // 32x32, 256 spp, seed 2, 0 bounces. Horizontal orthographic rays (heights -1.5..1.5 m) cross
    // 4 m of absorbing fog that falls with height (density 0.25 at y = 0.5, falloff 1/m) to an
    // emitting wall: each row sees exp(-0.25 exp(-(y - 0.5)) x 4), within 4.5 standard errors per row
    // (the row's 32 pixels pooled, + 0.002); the row means span 0.001 to 0.68.
    void heightFogTransmissionFollowsHeight() {
        Scene scene;
        const MaterialId wall = scene.materials.add(lambert(glm::vec3(0.0f), glm::vec3(1.0f)));
        addShape(scene, ShapeKind::Box, wall, {0.0f, 0.0f, -4.5f}, 0.5f, glm::vec3(20.0f, 20.0f, 1.0f));
        addOrthographicCamera(scene, glm::vec3(0.0f), {0.0f, 0.0f, -1.0f}, 1.5f);
        scene.settings.fog = {.density = 0.25f, .color = glm::vec3(0.0f), .heightFalloff = 1.0f, .baseHeight = 0.5f};
        const int size = 32, spp = 256;
        const auto out = render(scene, size, spp, 2, 0);
        for (int row = 0; row < size; ++row) {
            double expected = 0.0;
            for (int sub = 0; sub < 16; ++sub) {
                const double y = 1.5 - 3.0 * (row + (sub + 0.5) / 16.0) / size; // rows go top-down
                expected += std::exp(-0.25 * std::exp(-(y - 0.5)) * 4.0) / 16.0;
            }
            const Estimate e = estimate(out, size, spp, 0, [row](int, int r) { return r == row; });
            QVERIFY2(std::abs(e.mean - expected) < 4.5 * e.sigma + 0.002, qPrintable(QString("row %1: ").arg(row) + describe(e, expected)));
        }
    }

    // 32x32, 256 spp, seed 3, 1 bounce. Orthographic rays through a sphere (radius 1) of a
    // scattering medium with per-channel extinction (attenuation colour 0.2, 0.5, 0.8 at 0.5 m) in
    // front of an emitting wall, behind a real interface (IOR 1.001: it blocks shadow rays and its
    // crossings are bounces, but bends rays by 1e-3 at most). At 1 bounce, light scattered inside
    // never gets out (a second vertex inside ends the path), so each pixel sees the wall through the
    // unscattered share exp(-sigma_c x chord), averaged over the pixel: tests the spectral-MIS
    // free-flight weights per channel, within 4.5 standard errors per pixel + 0.003.
    void scatteringVolumeTransmitsPerChannel() {
        Scene scene;
        const glm::vec3 colour(0.2f, 0.5f, 0.8f);
        const float distance = 0.5f;
        Material volume = scatteringVolume(colour, distance, glm::vec3(0.9f), 0.3f);
        volume.ior = 1.001f;
        addShape(scene, ShapeKind::Sphere, scene.materials.add(volume), glm::vec3(0.0f), 1.0f);
        addShape(scene, ShapeKind::Box, scene.materials.add(lambert(glm::vec3(0.0f), glm::vec3(1.0f))), {0.0f, 0.0f, -2.5f},
                 0.5f, glm::vec3(20.0f, 20.0f, 1.0f));
        addOrthographicCamera(scene, {0.0f, 0.0f, 3.0f}, {0.0f, 0.0f, -1.0f}, 1.2f);
        const int size = 32, spp = 256;
        const auto out = render(scene, size, spp, 3, 1);
        const double pixelSize = 2.4 / size;
        for (int y = 0; y < size; ++y) {
            for (int x = 0; x < size; ++x) {
                for (int c = 0; c < 3; ++c) {
                    const double sigma = -std::log(colour[c]) / distance;
                    double expected = 0.0;
                    for (int sy = 0; sy < 8; ++sy) {
                        for (int sx = 0; sx < 8; ++sx) {
                            const double px = -1.2 + (x + (sx + 0.5) / 8.0) * pixelSize;
                            const double py = 1.2 - (y + (sy + 0.5) / 8.0) * pixelSize;
                            const double r2 = px * px + py * py;
                            expected += r2 < 1.0 ? std::exp(-sigma * 2.0 * std::sqrt(1.0 - r2)) : 1.0;
                        }
                    }
                    expected /= 64.0;
                    const double value = pixel(out.radiance, size, x, y, c);
                    const double se = std::sqrt(out.variance[std::size_t(y * size + x) * 3 + std::size_t(c)] / spp);
                    QVERIFY2(std::abs(value - expected) < 4.5 * se + 0.003,
                             qPrintable(QString("pixel %1,%2 channel %3: %4, expected %5, standard error %6").arg(x).arg(y).arg(c)
                                            .arg(value).arg(expected).arg(se)));
                }
            }
        }
    }

    // 24x24, 1024 spp, seed 10, 0 bounces: single scattering in a volume lit from outside. A sphere
    // (radius 1) of grey medium (extinction 1.2/m, albedo 0.8, g 0.3) behind an IOR-1 boundary, a
    // point light (20 W/sr raw) 3 m above its centre, orthographic rays along -Z. Paths and shadow
    // rays cross the index-matched boundary (no bounce taken), so each pixel is the integral along its chord of
    // sigma_s T(entry, s) HG(cos) I / r^2 T(s, exit towards the light), computed here (4x4 per
    // pixel): within 4.5 standard errors + 1 % of the peak per pixel, the image sum within 1 %.
    void volumeLitThroughItsBoundaryMatchesSingleScattering() {
        Scene scene;
        scene.settings.lightUnits = LightUnits::Raw;
        const double sigmaT = 1.2, albedo = 0.8, g = 0.3, intensity = 20.0;
        const float attenuation = float(std::exp(-sigmaT * 0.5)); // at 0.5 m
        addShape(scene, ShapeKind::Sphere, scene.materials.add(scatteringVolume(glm::vec3(attenuation), 0.5f, glm::vec3(float(albedo)), float(g))),
                 glm::vec3(0.0f), 1.0f);
        Light lamp;
        lamp.intensity = float(intensity);
        const glm::dvec3 lightAt(0.0, 3.0, 0.0);
        addNode(scene, "lamp", lamp, glm::vec3(lightAt));
        addOrthographicCamera(scene, {0.0f, 0.0f, 3.0f}, {0.0f, 0.0f, -1.0f}, 1.2f);
        const int size = 24, spp = 1024;
        const auto out = render(scene, size, spp, 10, 0);

        const auto alongChord = [&](double px, double py) {
            const double r2 = px * px + py * py;
            if (r2 >= 1.0) return 0.0;
            const double half = std::sqrt(1.0 - r2);
            const int steps = 400;
            double sum = 0.0;
            for (int i = 0; i < steps; ++i) {
                const double s = (i + 0.5) * 2.0 * half / steps;
                const glm::dvec3 at(px, py, half - s);
                const glm::dvec3 toLight = lightAt - at;
                const double r = glm::length(toLight);
                const glm::dvec3 w = toLight / r;
                const double b = glm::dot(at, w);
                const double exit = -b + std::sqrt(std::max(b * b - (glm::dot(at, at) - 1.0), 0.0));
                const double cosTheta = -w.z; // travel is -Z
                sum += sigmaT * albedo * std::exp(-sigmaT * s) * phase(cosTheta, g) * intensity / (r * r) * std::exp(-sigmaT * exit);
            }
            return sum * 2.0 * half / steps;
        };
        compareWithExpected(out, size, spp, expectedImage(size, glm::dvec2(0.0), 1.2, 4, alongChord));
    }

    // 32x32, 512 spp, seed 4, 64 bounces. The furnace room filled with fog that scatters all it
    // extinguishes (density 0.3, albedo 1, g 0.5, falling with height): radiance stays 1 everywhere.
    // Paths scatter in the fog, see the emitting wall through next-event estimation (with the
    // fog's transmittance on shadow rays) and by phase sampling, weighted by MIS. Image mean within
    // 0.5 % of 1, every pixel within 5 standard errors (its own, or the image's pooled one where
    // that is larger: a low pixel's own variance estimate runs small).
    void albedoOneFogFurnaceIsOne() {
        Scene scene = furnaceRoom();
        addPerspectiveCamera(scene, glm::vec3(0.0f), {0.0f, 0.0f, -1.0f}, 1.0f);
        scene.settings.fog = {.density = 0.3f, .color = glm::vec3(1.0f), .anisotropy = 0.5f, .heightFalloff = 0.2f};
        checkFurnace(render(scene, 32, 512, 4, 64), 512);
    }

    // 32x32, 512 spp, seed 5, 64 bounces. An albedo-1 scattering sphere (radius 1.5, extinction 0.3,
    // 0.6 and 1.2 per metre, g -0.3) behind an IOR-1 boundary in the furnace room: radiance 1
    // everywhere. (Thicker media scatter a path more often than the bounce limit allows.)
    void albedoOneVolumeFurnaceIsOne() {
        Scene scene = furnaceRoom();
        const glm::vec3 colour(std::exp(-0.15f), std::exp(-0.3f), std::exp(-0.6f)); // at 0.5 m
        addShape(scene, ShapeKind::Sphere, scene.materials.add(scatteringVolume(colour, 0.5f, glm::vec3(1.0f), -0.3f)),
                 glm::vec3(0.0f), 1.5f);
        addPerspectiveCamera(scene, {0.0f, 0.0f, 4.0f}, glm::vec3(0.0f), 0.9f);
        checkFurnace(render(scene, 32, 512, 5, 64), 512);
    }

    // 32x32, 1024 spp, seed 6, 0 bounces: single scattering. A spot light (10 W/sr raw, cone 0.3 to
    // 0.4 rad, 2 m up, shining down) in a homogeneous fog (density 0.15, albedo 0.8, g 0.4), seen by
    // horizontal orthographic rays from 0.5 to 2.5 m below it. Each pixel against the integral along its rays (8x8 per pixel)
    // of sigma_s T(0, s) HG(cos) I falloff / r^2 T(r), within 4.5 standard errors + 1 % of the peak.
    void spotBeamInFogMatchesSingleScattering() {
        Scene scene;
        scene.settings.lightUnits = LightUnits::Raw;
        Light spot;
        spot.type = LightType::Spot;
        const float intensity = 10.0f;
        spot.intensity = intensity;
        spot.innerConeAngle = 0.3f;
        spot.outerConeAngle = 0.4f;
        const glm::vec3 lightAt(0.0f, 2.0f, 0.0f);
        addNode(scene, "spot", spot, lightAt, lookRotation({0.0f, -1.0f, 0.0f}, {0.0f, 0.0f, -1.0f}));
        const float density = 0.15f, albedo = 0.8f, g = 0.4f;
        scene.settings.fog = {.density = density, .color = glm::vec3(albedo), .anisotropy = g};
        addOrthographicCamera(scene, {0.0f, 0.5f, 5.0f}, {0.0f, 0.0f, -1.0f}, 1.0f); // rays from 0.5 m below the light down
        const int size = 32, spp = 1024;
        const auto out = render(scene, size, spp, 6, 0);

        const auto singleScattering = [&](double px, double py) {
            const double cosOuter = std::cos(0.4), cosInner = std::cos(0.3);
            double sum = 0.0;
            const double ds = 0.002;
            for (double s = 0.5 * ds; s < 10.0; s += ds) {
                const glm::dvec3 at(px, py, 5.0 - s);
                const glm::dvec3 toLight = glm::dvec3(lightAt) - at;
                const double r = glm::length(toLight);
                const glm::dvec3 wi = toLight / r;
                const double ramp = std::clamp((wi.y - cosOuter) / (cosInner - cosOuter), 0.0, 1.0); // the spot shines along -Y
                if (ramp <= 0.0) continue;
                const double cosTheta = -wi.z; // travel is -Z
                sum += density * albedo * std::exp(-density * s) * phase(cosTheta, g) * intensity * ramp * ramp / (r * r) * std::exp(-density * r) * ds;
            }
            return sum;
        };
        compareWithExpected(out, size, spp, expectedImage(size, {0.0, 0.5}, 1.0, 8, singleScattering));
    }

    // A scene without fog or scattering materials compiles no medium code, and its pixels do not
    // change when a scattering material that nothing uses is added (the variant's surfaces in
    // vacuum draw the same random numbers).
    void mediaVariantKeepsSurfacePixels() {
        Scene scene;
        const MaterialId ground = scene.materials.add(lambert(glm::vec3(0.7f)));
        addShape(scene, ShapeKind::GroundPlane, ground, glm::vec3(0.0f));
        addShape(scene, ShapeKind::Sphere, scene.materials.add(lambert(glm::vec3(0.3f, 0.6f, 0.9f))), {0.0f, 0.5f, 0.0f}, 0.5f);
        addSun(scene, glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f)), 2000.0f);
        addPerspectiveCamera(scene, {0.0f, 1.0f, 3.0f}, {0.0f, 0.4f, 0.0f}, 0.8f);
        const auto plain = render(scene, 24, 8, 7, 3);
        scene.materials.add(scatteringVolume(glm::vec3(0.5f), 1.0f, glm::vec3(0.5f), 0.0f));
        const auto withMedia = render(scene, 24, 8, 7, 3);
        QCOMPARE(withMedia.radiance, plain.radiance);
    }

    // 16x16, 1024 spp, seed 8, 0 bounces: single scattering from an area emitter. The camera at the
    // centre of a black sphere (radius 5) emitting 1, filled with fog (density 0.3, albedo 1, g 0):
    // every direction sees exp(-sigma R) + integral over s of sigma exp(-sigma s) L_in(s), where
    // L_in(s) = 1/2 integral over mu of exp(-sigma d(s, mu)) and d is the distance to the wall from
    // radius s at angle acos(mu) to the radial direction (computed here). Image mean within 4
    // standard errors.
    void areaEmitterInFogMatchesSingleScattering() {
        Scene scene;
        addShape(scene, ShapeKind::Sphere, scene.materials.add(lambert(glm::vec3(0.0f), glm::vec3(1.0f))), glm::vec3(0.0f), 5.0f);
        addPerspectiveCamera(scene, glm::vec3(0.0f), {0.2f, 0.1f, -1.0f}, 1.0f);
        const double sigma = 0.3, radius = 5.0;
        scene.settings.fog = {.density = float(sigma), .color = glm::vec3(1.0f)};
        const int size = 16, spp = 1024;
        const auto out = render(scene, size, spp, 8, 0);
        double expected = std::exp(-sigma * radius);
        const int steps = 2000;
        for (int i = 0; i < steps; ++i) {
            const double r = (i + 0.5) * radius / steps;
            double inScattered = 0.0;
            for (int j = 0; j < steps; ++j) {
                const double mu = -1.0 + (j + 0.5) * 2.0 / steps;
                const double d = -r * mu + std::sqrt(radius * radius - r * r * (1.0 - mu * mu));
                inScattered += std::exp(-sigma * d) / steps; // 1/2 x integral over 2 units of mu
            }
            expected += sigma * std::exp(-sigma * r) * inScattered * radius / steps;
        }
        const Estimate e = estimate(out, size, spp, 0, [](int, int) { return true; });
        QVERIFY2(std::abs(e.mean - expected) < 4.0 * e.sigma, qPrintable(describe(e, expected)));
    }

    // The guide buffers (depth, normal, object id) describe the surface behind the fog, not the random
    // point where a camera ray scattered, so the real-time denoisers reproject and edge-stop on a
    // stable surface: with fog they equal those of the same scene without it (16x16, 4 spp).
    void fogKeepsTheGuideBuffersOfTheSurfaces() {
        Scene scene;
        addShape(scene, ShapeKind::GroundPlane, scene.materials.add(lambert(glm::vec3(0.7f))), glm::vec3(0.0f));
        addShape(scene, ShapeKind::Sphere, scene.materials.add(lambert(glm::vec3(0.5f))), {0.0f, 0.5f, 0.0f}, 0.5f);
        Light lamp;
        lamp.intensity = 50.0f;
        addNode(scene, "lamp", lamp, {1.0f, 2.0f, 1.0f});
        addPerspectiveCamera(scene, {0.0f, 1.0f, 3.0f}, {0.0f, 0.3f, 0.0f}, 0.9f);
        const auto clear = render(scene, 16, 4, 9, 2);
        scene.settings.fog = {.density = 0.8f, .color = glm::vec3(0.9f)};
        const auto foggy = render(scene, 16, 4, 9, 2);
        QCOMPARE(foggy.depth, clear.depth);
        QCOMPARE(foggy.objectId, clear.objectId);
        for (std::size_t i = 0; i < clear.normal.size(); ++i)
            QVERIFY2(std::abs(foggy.normal[i] - clear.normal[i]) < 1e-5f, qPrintable(QString("normal component %1").arg(i)));
        QVERIFY(foggy.radiance != clear.radiance); // the fog is there
    }

private:
    static void checkFurnace(const renderer::RenderOutput& out, int spp) {
        for (int c = 0; c < 3; ++c) {
            const ChannelStats s = channelStats(out.radiance, c);
            QVERIFY2(std::abs(s.mean - 1.0) < 0.005, qPrintable(QString("channel %1 mean %2").arg(c).arg(s.mean)));
        }
        double pooledVariance = 0.0;
        for (const float v : out.variance) pooledVariance += v;
        const double sigma = std::sqrt(pooledVariance / static_cast<double>(out.variance.size()) / spp);
        for (std::size_t i = 0; i < out.variance.size(); ++i) {
            const double value = out.radiance[i / 3 * 4 + i % 3];
            const double se = std::max(sigma, std::sqrt(double(out.variance[i]) / spp));
            QVERIFY2(std::abs(value - 1.0) <= 5.0 * se, qPrintable(QString("pixel %1: %2, standard error %3").arg(i / 3).arg(value).arg(se)));
        }
    }
};

QTEST_GUILESS_MAIN(TestRenderMedia)
#include "test_render_media.moc"
