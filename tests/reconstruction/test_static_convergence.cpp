// A still view converges: Full fades into the running mean and ends exactly on the accumulated
// image; before that, the filtered frames are much closer to the converged image than raw samples.
#include "reconstruction_fixture.h"

#include <QtTest>

using namespace glint;
using namespace glint::test;

class TestStaticConvergence : public QObject {
    Q_OBJECT
    std::unique_ptr<Harness> h_;

private slots:
    void initTestCase() { h_ = std::make_unique<Harness>(); }

    // Tolerance: after convergeFadeSamples frames Full equals Accumulate with as many samples
    // (the same sample sequence): relMSE below 1e-10, i.e. equal up to float rounding.
    void fullEndsOnTheAccumulatedImage() {
        const RoomScene room = makeRoom();
        const auto camera = cameraAt(room.scene, 0.0f);
        h_->frames.setSettings(settingsFor(renderer::Configuration::Full));
        h_->frames.setScene(room.scene);
        std::vector<float> full;
        for (int i = 0; i < renderer::convergeFadeSamples; ++i) full = h_->frame(camera);
        QCOMPARE(h_->frames.sampleCount(), renderer::convergeFadeSamples);

        renderer::FrameSettings acc = settingsFor(renderer::Configuration::Accumulate);
        h_->frames.setSettings(acc);
        std::vector<float> accumulated;
        for (int i = 0; i < renderer::convergeFadeSamples; ++i) accumulated = h_->frame(camera);
        const double error = relMse(full, accumulated);
        qInfo("Full after %d frames vs Accumulate %d spp: relMSE %.3g", renderer::convergeFadeSamples,
              renderer::convergeFadeSamples, error);
        QVERIFY2(error < 1e-10, qPrintable(QString::number(error)));
    }

    // Tolerance: after 8 frames Full's relMSE against a 256-spp image is below half of a raw 1-spp
    // frame's. The other configurations' errors are printed for docs/DENOISING.md.
    void filtersHelpBeforeConvergence() {
        const RoomScene room = makeRoom();
        const auto camera = cameraAt(room.scene, 0.0f);
        const auto reference = h_->converged(room.scene, camera, 256);
        dump(reference, "static_reference");
        h_->frames.setSettings(settingsFor(renderer::Configuration::Accumulate));
        h_->frames.setScene(room.scene);
        const double raw = relMse(h_->frame(camera), reference);
        double full = 0.0;
        for (auto c : {renderer::Configuration::Baseline, renderer::Configuration::Realistic, renderer::Configuration::Full,
                       renderer::Configuration::Heavy, renderer::Configuration::Accumulate}) {
            h_->frames.setSettings(settingsFor(c));
            h_->frames.setScene(room.scene);
            std::vector<float> image;
            for (int i = 0; i < 8; ++i) image = h_->frame(camera);
            const double error = relMse(image, reference);
            if (c == renderer::Configuration::Full) full = error;
            qInfo("still view, 8 frames, %s: relMSE %.4f", std::string(renderer::configurationName(c)).c_str(), error);
            dump(image, "static_" + std::string(renderer::configurationName(c)) + "_8");
            dump(errorImage(image, reference), "static_error_" + std::string(renderer::configurationName(c)) + "_8");
        }
        qInfo("raw 1 spp: relMSE %.4f", raw);
        QVERIFY2(full < 0.5 * raw, qPrintable(QString("Full %1, raw %2").arg(full).arg(raw)));
    }
};

QTEST_APPLESS_MAIN(TestStaticConvergence)
#include "test_static_convergence.moc"
