// A statistical image test in the style of Mitsuba 3's test_renders.py: with the independent
// sampler, a render's pixels are z-tested against a reference mean and variance, with a Sidak-
// corrected significance over all pixels. The reference is Glint's own render (another seed, 16x the
// samples), made at test time: this checks that the estimator is consistent and unbiased across
// seeds and sample counts, not that it matches another renderer. Rare events (a small
// bright highlight, a small object seen from afar) break such tests without any bias, so the scene
// has none. On failure the image, reference and z-score images are
// written as EXR into a kept temp dir.
#include "scene_builder.h"

#include "renderer/offline_render.h"

#include <OpenImageIO/imageio.h>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <memory>

using namespace glint;
using namespace glint::test;

namespace {

// Two coloured spheres inside a closed grey sphere that glows (albedo 0.5, emission 0.5): every
// pixel sees its light along paths that are common, not rare (no small light, no small object seen
// from afar), so the sample variance of a few dozen samples is a fair estimate.
Scene enclosure() {
    Scene scene;
    const MaterialId wall = scene.materials.add(lambert(glm::vec3(0.5f), glm::vec3(0.5f)));
    const MaterialId red = scene.materials.add(lambert({0.8f, 0.2f, 0.1f}));
    const MaterialId blue = scene.materials.add(lambert({0.1f, 0.3f, 0.8f}));
    addShape(scene, ShapeKind::Sphere, wall, glm::vec3(0.0f), 3.0f);
    addShape(scene, ShapeKind::Sphere, red, {-0.6f, 0.0f, 0.0f}, 0.7f);
    addShape(scene, ShapeKind::Sphere, blue, {0.8f, 0.2f, 0.3f}, 0.5f);
    addPerspectiveCamera(scene, {0.0f, 0.5f, 2.5f}, glm::vec3(0.0f), 1.2f);
    return scene;
}

void writeExr(const std::string& file, const std::vector<float>& rgb, int width, int height) {
    auto out = OIIO::ImageOutput::create(file);
    if (!out || !out->open(file, OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT))) return;
    out->write_image(OIIO::TypeDesc::FLOAT, rgb.data());
    out->close();
}

} // namespace

class TestRenderZTest : public QObject {
    Q_OBJECT
private slots:
    // 24x24, independent sampler, 8 bounces: seed 3 at 64 spp against seed 4 at 1024 spp. For each
    // pixel and channel z = (x - r) / sqrt(var_r (1/64 + 1/1024)); fail when its two-sided p-value
    // is below the Sidak-corrected level for alpha = 0.01 over all 1728 tests.
    void renderMatchesReferenceStatistically() {
        renderer::OfflineRenderer renderer;
        const Scene scene = enclosure();
        renderer::RenderRequest request;
        request.width = request.height = 24;
        request.bounces = 8;
        request.independentSampler = true;
        request.spp = 64;
        request.seed = 3;
        const auto image = renderer.render(scene, request);
        request.spp = 1024;
        request.seed = 4;
        const auto reference = renderer.render(scene, request);

        const std::size_t tests = image.variance.size();
        const double alpha = 1.0 - std::pow(1.0 - 0.01, 1.0 / static_cast<double>(tests));
        std::vector<float> imageRgb, referenceRgb, zScores;
        double worstP = 1.0;
        QString worst;
        for (std::size_t i = 0; i < tests; ++i) {
            const double x = image.radiance[i / 3 * 4 + i % 3], r = reference.radiance[i / 3 * 4 + i % 3];
            // Both sides with the reference's variance (as Mitsuba does): 64 samples often miss rare
            // events (a ray hitting a small object) and would understate their own variance.
            const double variance = reference.variance[i] * (1.0 / 64.0 + 1.0 / 1024.0);
            const double z = variance > 0.0 ? (x - r) / std::sqrt(variance) : (x == r ? 0.0 : INFINITY);
            const double p = std::erfc(std::abs(z) / std::sqrt(2.0));
            if (p < worstP) {
                worstP = p;
                worst = QString("pixel %1 channel %2: %3 vs %4, z %5").arg(i / 3).arg(i % 3).arg(x).arg(r).arg(z);
            }
            imageRgb.push_back(static_cast<float>(x));
            referenceRgb.push_back(static_cast<float>(r));
            zScores.push_back(static_cast<float>(z));
        }
        if (worstP < alpha) {
            QTemporaryDir dir;
            dir.setAutoRemove(false);
            writeExr(dir.filePath("image.exr").toStdString(), imageRgb, 24, 24);
            writeExr(dir.filePath("reference.exr").toStdString(), referenceRgb, 24, 24);
            writeExr(dir.filePath("z_scores.exr").toStdString(), zScores, 24, 24);
            QFAIL(qPrintable(QString("smallest p-value %1 < %2 (%3); images in %4").arg(worstP).arg(alpha).arg(worst).arg(dir.path())));
        }
    }
};

QTEST_APPLESS_MAIN(TestRenderZTest)
#include "test_render_ztest.moc"
