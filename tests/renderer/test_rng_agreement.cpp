// The GPU's random numbers equal the C++ twin's bit for bit (64x64 pixels, samples 0 and 77,
// seeds 0 and 0xdeadbeef; the low-discrepancy stream also at a sample index above 2^31): what the
// CPU tests prove about the streams holds on the GPU.
#include "renderer/cpu_twin/glsl_twin.h"
#include "renderer/gl/fullscreen_triangle.h"
#include "renderer/gl/headless_context.h"
#include "renderer/gl/render_target.h"
#include "renderer/gl/shader_program.h"

#include <QTest>

using namespace glint;

class TestRngAgreement : public QObject {
    Q_OBJECT
private slots:
    void gpuStreamEqualsCpuTwin_data() {
        QTest::addColumn<uint>("sampleIndex");
        QTest::addColumn<uint>("seed");
        QTest::newRow("sample 0, seed 0") << 0u << 0u;
        QTest::newRow("sample 77, seed 0xdeadbeef") << 77u << 0xdeadbeefu;
    }
    void gpuStreamEqualsCpuTwin() {
        QFETCH(uint, sampleIndex);
        QFETCH(uint, seed);
        gl::HeadlessContext context;
        const gl::ShaderProgram program({"fullscreen.vert.glsl", "probes/rng_probe.frag.glsl", {}, {"outValues"}});
        const gl::RenderTarget target(64, 64, {GL_RGBA32F});
        const gl::FullscreenTriangle triangle;
        program.use();
        glUniform1ui(program.uniform("uSampleIndex"), sampleIndex);
        glUniform1ui(program.uniform("uSeed"), seed);
        target.bindForDrawing();
        triangle.draw();
        const std::vector<float> gpu = target.readRgba(0);
        int compared = 0;
        for (int y = 0; y < 64; ++y) {
            for (int x = 0; x < 64; ++x) {
                twin::Rng rng = twin::rngStart(twin::uvec2(x, y), sampleIndex, seed);
                const float a = twin::rand1(rng);
                const float b = twin::rand1(rng);
                const twin::vec2 cd = twin::rand2(rng);
                const float cpu[4] = {a, b, cd.x, cd.y};
                for (int c = 0; c < 4; ++c) {
                    const float value = gpu[(static_cast<std::size_t>(y) * 64 + static_cast<std::size_t>(x)) * 4 + static_cast<std::size_t>(c)];
                    QVERIFY2(value == cpu[c], qPrintable(QString("pixel %1,%2 value %3: gpu %4 cpu %5").arg(x).arg(y).arg(c).arg(value).arg(cpu[c])));
                    ++compared;
                }
            }
        }
        QCOMPARE(compared, 64 * 64 * 4);
    }

    void gpuLowDiscrepancyStreamEqualsCpuTwin_data() {
        QTest::addColumn<uint>("sampleIndex");
        QTest::addColumn<uint>("seed");
        QTest::newRow("sample 0, seed 0") << 0u << 0u;
        QTest::newRow("sample 77, seed 0xdeadbeef") << 77u << 0xdeadbeefu;
        QTest::newRow("sample 2^31 + 5, seed 3") << 0x80000005u << 3u;
    }
    void gpuLowDiscrepancyStreamEqualsCpuTwin() {
        QFETCH(uint, sampleIndex);
        QFETCH(uint, seed);
        gl::HeadlessContext context;
        const gl::ShaderProgram program({"fullscreen.vert.glsl", "probes/sampler_probe.frag.glsl", {}, {"outValues", "outMoreValues"}});
        const gl::RenderTarget target(64, 64, {GL_RGBA32F, GL_RGBA32F});
        const gl::FullscreenTriangle triangle;
        program.use();
        glUniform1ui(program.uniform("uSampleIndex"), sampleIndex);
        glUniform1ui(program.uniform("uSeed"), seed);
        target.bindForDrawing();
        triangle.draw();
        const std::vector<float> gpu[2] = {target.readRgba(0), target.readRgba(1)};
        int compared = 0;
        for (int y = 0; y < 64; ++y) {
            for (int x = 0; x < 64; ++x) {
                twin::Rng rng = twin::rngStartLowDiscrepancy(twin::uvec2(x, y), sampleIndex, seed);
                const float a = twin::rand1(rng);
                const twin::vec2 b = twin::rand2(rng);
                const twin::vec3 c = twin::rand3(rng);
                const twin::vec4 d = twin::rand4(rng);
                const float cpu[8] = {a, b.x, b.y, c.x, c.y, c.z, d.x, d.w};
                for (int i = 0; i < 8; ++i) {
                    const float value = gpu[i / 4][(static_cast<std::size_t>(y) * 64 + static_cast<std::size_t>(x)) * 4 + static_cast<std::size_t>(i % 4)];
                    QVERIFY2(value == cpu[i], qPrintable(QString("pixel %1,%2 value %3: gpu %4 cpu %5").arg(x).arg(y).arg(i).arg(value).arg(cpu[i])));
                    ++compared;
                }
            }
        }
        QCOMPARE(compared, 64 * 64 * 8);
    }
};

QTEST_APPLESS_MAIN(TestRngAgreement)
#include "test_rng_agreement.moc"
