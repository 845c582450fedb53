// The converge stage (shaders/reconstruction/converge.frag.glsl) on constant images, known answers:
// the reconstructed frame 0.25, the still mean 4 (alpha 0.5). With n still samples the output is
// mix(frame, mean, n / 16), except at n <= 1, where the mean is the frame itself and gets no weight
// (so a moving view, always at its first sample, never needs the filtered mean), and from 16 on
// the mean alone, alpha included. Tolerance: float rounding of one mix (1e-6 relative).
#include "renderer/gl/fullscreen_triangle.h"
#include "renderer/gl/headless_context.h"
#include "renderer/gl/program_cache.h"
#include "renderer/gl/render_target.h"
#include "renderer/passes/fullscreen_stage.h"
#include "renderer/passes/reconstruction.h"

#include <epoxy/gl.h>

#include <QtTest>

using namespace glint;

namespace {

constexpr int kSize = 4;
constexpr float kFrame = 0.25f;
constexpr float kMean = 4.0f;

void fill(const gl::RenderTarget& target, float value, float alpha) {
    target.bindForDrawing();
    const float colour[4] = {value, value, value, alpha};
    glClearBufferfv(GL_COLOR, 0, colour);
}

} // namespace

class TestConvergeFade : public QObject {
    Q_OBJECT
    std::unique_ptr<gl::HeadlessContext> context_;

    std::vector<float> converge(int stillSamples) {
        gl::ProgramCache programs;
        gl::FullscreenTriangle triangle;
        const gl::RenderTarget frame(kSize, kSize, {GL_RGBA32F}), mean(kSize, kSize, {GL_RGBA32F}),
            out(kSize, kSize, {GL_RGBA32F});
        fill(frame, kFrame, 1.0f);
        fill(mean, kMean, 0.5f);
        renderer::runStage(programs, triangle,
                           {"reconstruction/converge.frag.glsl",
                            {"outRadiance"},
                            {{"uReconstructed", frame, 0}, {"uStillMean", mean, 0}},
                            [&](const gl::ShaderProgram& p) {
                                glUniform1f(p.uniform("uStillSamples"), float(stillSamples));
                                glUniform1f(p.uniform("uFadeSamples"), float(renderer::convergeFadeSamples));
                            }},
                           out);
        return out.readRgba(0);
    }

private slots:
    void initTestCase() { context_ = std::make_unique<gl::HeadlessContext>(); }

    void weightsTheMeanByItsSamples_data() {
        QTest::addColumn<int>("samples");
        QTest::addColumn<float>("weight"); // of the mean
        QTest::newRow("none") << 0 << 0.0f;
        QTest::newRow("the first: the frame itself") << 1 << 0.0f;
        QTest::newRow("2") << 2 << 2.0f / 16.0f;
        QTest::newRow("8") << 8 << 0.5f;
        QTest::newRow("15") << 15 << 15.0f / 16.0f;
        QTest::newRow("16: the mean") << 16 << 1.0f;
        QTest::newRow("64") << 64 << 1.0f;
    }
    void weightsTheMeanByItsSamples() {
        QFETCH(int, samples);
        QFETCH(float, weight);
        const std::vector<float> pixels = converge(samples);
        QCOMPARE(pixels.size(), std::size_t(kSize * kSize * 4));
        const float expected = kFrame + (kMean - kFrame) * weight;
        for (std::size_t i = 0; i < pixels.size(); i += 4) {
            for (std::size_t c = 0; c < 3; ++c)
                QVERIFY2(std::abs(pixels[i + c] - expected) <= 1e-6f * kMean,
                         qPrintable(QString("pixel %1: %2, expected %3").arg(i / 4).arg(pixels[i + c]).arg(expected)));
            QCOMPARE(pixels[i + 3], 0.5f); // the mean's alpha (coverage), whatever the weight
        }
    }
};

QTEST_GUILESS_MAIN(TestConvergeFade)
#include "test_converge_fade.moc"
