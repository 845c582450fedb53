// The GLSL traversal (shaders/bvh/) reads the flattened buffers exactly as the CPU twin does: the
// same rays through the bunny and transformed instances give the same hits on the GPU and the CPU.
// 128 x 128 rays; the triangle slot, instance and object id must agree for every ray, t within 1e-5
// relative and barycentrics within 1e-4 (GPU division may differ by an ULP or two; the watertight
// edge tests decide the same way).
#include "bvh_test_scenes.h"
#include "renderer/bvh/bvh_layout.h"
#include "renderer/bvh/size_check.h"
#include "renderer/bvh/traverse.h"
#include "renderer/bvh/validate.h"
#include "renderer/gl/fullscreen_triangle.h"
#include "renderer/gl/headless_context.h"
#include "renderer/gl/render_target.h"
#include "renderer/gl/shader_program.h"
#include "renderer/gl/texture_buffer.h"

#include <glm/gtc/matrix_transform.hpp>

#include <QTest>

#include <cmath>

using namespace glint;
using namespace glint::bvh;
using namespace glint::bvh::test;

namespace {

constexpr int kSize = 128;

TestScene instancedBunnies()
{
    const glm::mat4 rotated = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0.3f, 0.0f, 0.0f)), 0.7f, glm::vec3(0, 1, 0));
    const glm::mat4 mirrored = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(-0.3f, 0.0f, 0.1f)), glm::vec3(-1.0f, 1.5f, 1.0f));
    return makeScene({loadBunny(), closedGridCube(6, 0.05f, glm::vec3(-0.15f))},
                     {{0, glm::mat4(1.0f)}, {0, rotated}, {0, mirrored}, {1, glm::translate(glm::mat4(1.0f), glm::vec3(0, -0.3f, 0))}});
}

struct GpuBuffers {
    gl::TextureBuffer nodes, levels, positions, vertices, instances;
    explicit GpuBuffers(const FlatScene& s)
        : nodes("BVH nodes", GL_RGBA32UI, s.nodes.data(), s.nodes.size(), 16),
          levels("BVH levels", GL_RGBA32UI, s.levels.data(), s.levels.size(), 16),
          positions("BVH triangle positions", GL_RGBA32F, s.trianglePositions.data(), s.trianglePositions.size(), 16),
          vertices("BVH triangle vertices", GL_RGBA32UI, s.triangleVertices.data(), s.triangleVertices.size(), 16),
          instances("BVH instances", GL_RGBA32UI, s.instances.data(), s.instances.size(), 16)
    {
    }
    void bind(const gl::ShaderProgram& program) const
    {
        nodes.bind(0, program.uniform(kNodesUniform));
        levels.bind(1, program.uniform(kLevelsUniform));
        positions.bind(2, program.uniform(kTrianglePositionsUniform));
        vertices.bind(3, program.uniform(kTriangleVerticesUniform));
        instances.bind(4, program.uniform(kInstancesUniform));
    }
};

} // namespace

class TestBvhGpu : public QObject {
    Q_OBJECT
private slots:
    void glslTraversalMatchesCpuTwin()
    {
        gl::HeadlessContext context;
        const TestScene scene = instancedBunnies();
        QCOMPARE(validateFlatScene(scene.flat), std::optional<std::string>{});
        QCOMPARE(checkTextureBufferSizes(scene.flat, static_cast<std::int64_t>(gl::maxTextureBufferTexels())), std::optional<std::string>{});

        Aabb bounds;
        for (const Aabb& box : scene.topLevel.worldBounds) bounds.grow(box);
        std::mt19937 rng(31u);
        std::vector<Ray> rays(kSize * kSize);
        std::vector<glm::vec4> origins, directions;
        for (Ray& ray : rays) {
            ray = randomRayThrough(rng, bounds);
            origins.emplace_back(ray.origin, 1e30f);
            directions.emplace_back(ray.direction, 0.0f);
        }
        const gl::TextureBuffer originBuffer("ray origins", GL_RGBA32F, origins.data(), origins.size(), 16);
        const gl::TextureBuffer directionBuffer("ray directions", GL_RGBA32F, directions.data(), directions.size(), 16);
        const GpuBuffers buffers(scene.flat);
        const gl::ShaderProgram program({"fullscreen.vert.glsl", "bvh/ray_query_probe.frag.glsl", {}, {"outHit", "outInstance"}});
        const gl::RenderTarget target(kSize, kSize, {GL_RGBA32F, GL_RGBA32F});
        program.use();
        buffers.bind(program);
        originBuffer.bind(5, program.uniform("uRayOrigins"));
        directionBuffer.bind(6, program.uniform("uRayDirections"));
        glUniform1i(program.uniform(kTopLevelUniform), scene.flat.topLevel);
        glUniform1i(program.uniform("uRayQueryWidth"), kSize);
        target.bindForDrawing();
        gl::FullscreenTriangle().draw();
        const std::vector<float> hits = target.readRgba(0);
        const std::vector<float> instances = target.readRgba(1);

        int hitCount = 0;
        for (std::size_t i = 0; i < rays.size(); ++i) {
            const RayHit cpu = intersectClosest(scene.flat, rays[i], 1e30f);
            const float* gpuHit = &hits[4 * i];
            const float* gpuInstance = &instances[4 * i];
            const QString where = QString("ray %1").arg(i);
            QVERIFY2(static_cast<int>(gpuInstance[0]) == cpu.instance, qPrintable(where + QString(": instance %1 vs %2").arg(gpuInstance[0]).arg(cpu.instance)));
            QVERIFY2(gpuInstance[1] == (cpu.hit() ? 1.0f : 0.0f), qPrintable(where + ": occlusion differs"));
            if (!cpu.hit()) continue;
            ++hitCount;
            QVERIFY2(static_cast<int>(gpuHit[3]) == cpu.slot, qPrintable(where + QString(": slot %1 vs %2").arg(gpuHit[3]).arg(cpu.slot)));
            QVERIFY2(std::abs(gpuHit[0] - cpu.t) <= 1e-5f * cpu.t, qPrintable(where + QString(": t %1 vs %2").arg(gpuHit[0]).arg(cpu.t)));
            QVERIFY2(std::abs(gpuHit[1] - cpu.u) <= 1e-4f && std::abs(gpuHit[2] - cpu.v) <= 1e-4f,
                     qPrintable(where + QString(": barycentrics (%1, %2) vs (%3, %4)").arg(gpuHit[1]).arg(gpuHit[2]).arg(cpu.u).arg(cpu.v)));
            QCOMPARE(static_cast<std::uint32_t>(gpuInstance[2]), scene.topLevel.instances[static_cast<std::size_t>(cpu.instance)].objectId);
        }
        qInfo("%s: %d of %d rays hit", context.renderer().c_str(), hitCount, kSize * kSize);
        QVERIFY(hitCount > kSize * kSize / 4);
    }
};

QTEST_APPLESS_MAIN(TestBvhGpu)
#include "test_bvh_gpu.moc"
