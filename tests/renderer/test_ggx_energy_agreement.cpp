// The GGX energy tables the GPU reads from its uniform block (uploaded as GpuScene does) are the C++
// twin's arrays bit for bit, and the lookups through them (index math and bilinear weights) agree
// with the twin's on a 65 x 65 grid of (mu, roughness) that covers every cell and edge.
#include "renderer/cpu_twin/glsl_twin.h"
#include "renderer/gl/fullscreen_triangle.h"
#include "renderer/gl/headless_context.h"
#include "renderer/gl/render_target.h"
#include "renderer/gl/shader_program.h"
#include "renderer/gpu_scene/gpu_scene.h"

#include <QTest>

#include <cmath>

using namespace glint;

class TestGgxEnergyAgreement : public QObject {
    Q_OBJECT
private slots:
    void gpuTablesEqualCpuTwin() {
        gl::HeadlessContext context;
        const gl::ShaderProgram program({"fullscreen.vert.glsl", "probes/ggx_energy_probe.frag.glsl", {}, {"outEntries", "outLookups"}});
        const gl::Buffer tables = renderer::uploadGgxEnergyTables();
        const int n = 65;
        const gl::RenderTarget target(n, n, {GL_RGBA32F, GL_RGBA32F});
        const gl::FullscreenTriangle triangle;
        program.use();
        renderer::bindGgxEnergyTables(program, tables);
        target.bindForDrawing();
        triangle.draw();
        const std::vector<float> entries = target.readRgba(0);
        const std::vector<float> lookups = target.readRgba(1);
        const twin::vec3 f0(0.04f, 0.5f, 1.0f);
        float worst = 0.0f;
        for (int y = 0; y < n; ++y) {
            for (int x = 0; x < n; ++x) {
                const std::size_t p = (static_cast<std::size_t>(y) * n + static_cast<std::size_t>(x)) * 4;
                const std::size_t i = static_cast<std::size_t>(y * n + x) % 512;
                const float cpuEntries[4] = {twin::GGX_ALBEDO_TABLE[i], twin::GGX_FRESNEL_ALBEDO_TABLE[i],
                                             twin::GGX_AVERAGE_ALBEDO_TABLE[i % 32], twin::GGX_AVERAGE_FRESNEL_ALBEDO_TABLE[i % 32]};
                const float mu = float(x) * 0.015625f;
                const float roughness = float(y) * 0.015625f;
                const float cpuLookups[4] = {twin::ggxDirectionalAlbedo(mu, roughness), twin::ggxFresnelAlbedo(mu, roughness),
                                             twin::ggxAverageSchlickAlbedo(f0, roughness).x, twin::ggxMultipleScatteringScale(f0, mu, roughness).x};
                for (std::size_t c = 0; c < 4; ++c) {
                    QVERIFY2(entries[p + c] == cpuEntries[c],
                             qPrintable(QString("entry %1 of table %2: gpu %3 cpu %4").arg(i).arg(c).arg(entries[p + c]).arg(cpuEntries[c])));
                    const float error = std::abs(lookups[p + c] - cpuLookups[c]) / std::max(1.0f, std::abs(cpuLookups[c]));
                    worst = std::max(worst, error);
                    // Rounding alone (a driver may fuse or reorder the bilinear blend): a wrong index or
                    // weight is off by far more.
                    QVERIFY2(error <= 1e-6f, qPrintable(QString("mu %1 roughness %2 lookup %3: gpu %4 cpu %5")
                                                            .arg(mu).arg(roughness).arg(c).arg(lookups[p + c]).arg(cpuLookups[c])));
                }
            }
        }
        qInfo("largest relative difference of the lookups: %g", double(worst));
    }
};

QTEST_APPLESS_MAIN(TestGgxEnergyAgreement)
#include "test_ggx_energy_agreement.moc"
