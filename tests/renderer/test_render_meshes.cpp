// Triangle meshes through the BVH: they render like the analytic shapes they approximate, emissive
// triangles sampled as lights (with MIS) agree with the same emitter found by BSDF sampling alone,
// single-sided emitters light only what their front faces, and the Cornell box scene renders (a
// PNG is left in the test's temp dir).
#include "image_stats.h"
#include "mesh_builder.h"
#include "render_scene.h"
#include "scene_builder.h"

#include "renderer/offline_render.h"
#include "scene/io/scene_io.h"

#include <OpenImageIO/imageio.h>
#include <QTemporaryDir>
#include <QTest>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <memory>

using namespace glint;
using namespace glint::test;

namespace {

NodeId addMeshNode(Scene& scene, MeshId mesh, glm::vec3 position) {
    return addNode(scene, "mesh", MeshInstance{mesh}, position);
}

// How the emitter of squareLightOverGround is made: an analytic quad (emits from both sides), or a
// mesh quad: double-sided, or single-sided (front face only) with its front up, or turned down by a
// rotation, or by a mirroring scale (the winding turns around, the front stays the normal's side).
enum class Emitter { Shape, MeshDoubleSided, MeshFrontUp, MeshFrontDown, MeshFrontDownMirrored };

// A grey ground under a 1 m square emitter 1 m up (radiance 4), seen from the side and below.
Scene squareLightOverGround(Emitter emitter) {
    Scene scene;
    const MaterialId grey = scene.materials.add(lambert(glm::vec3(0.5f)));
    Material lightMaterial = lambert(glm::vec3(0.0f), glm::vec3(4.0f));
    lightMaterial.doubleSided = emitter == Emitter::MeshDoubleSided;
    const MaterialId light = scene.materials.add(lightMaterial);
    addShape(scene, ShapeKind::GroundPlane, grey, glm::vec3(0.0f));
    const glm::vec3 at(0.0f, 1.0f, 0.0f);
    if (emitter == Emitter::Shape) {
        addShape(scene, ShapeKind::Quad, light, at);
    } else {
        const MeshId quad = scene.meshes.add(quadMesh(1.0f, light)); // front (+Y, counter-clockwise) up
        if (emitter == Emitter::MeshFrontDown) addNode(scene, "mesh", MeshInstance{quad}, at, glm::angleAxis(glm::pi<float>(), glm::vec3(1.0f, 0.0f, 0.0f)));
        else if (emitter == Emitter::MeshFrontDownMirrored) addNode(scene, "mesh", MeshInstance{quad}, at, glm::quat(1.0f, 0.0f, 0.0f, 0.0f), {1.0f, -1.0f, 1.0f});
        else addMeshNode(scene, quad, at);
    }
    addPerspectiveCamera(scene, {0.0f, 0.6f, 3.0f}, glm::vec3(0.0f), 0.9f);
    return scene;
}

} // namespace

class TestRenderMeshes : public QObject {
    Q_OBJECT
    std::unique_ptr<renderer::OfflineRenderer> renderer_;

    renderer::RenderOutput render(const Scene& scene, int size, int spp, std::uint32_t seed, int bounces) {
        return test::renderScene(*renderer_, scene, size, spp, seed, bounces);
    }

private slots:
    void initTestCase() { renderer_ = std::make_unique<renderer::OfflineRenderer>(); }
    void cleanupTestCase() { renderer_.reset(); }

    // 32x32, 256 spp, seed 31, 2 bounces. The emitter as an analytic quad (found only by BSDF
    // sampling) and as a double-sided two-triangle mesh (light-sampled, MIS-weighted): image means
    // within 2 %.
    void emissiveMeshMatchesEmissiveShape() {
        const double shape = channelStats(render(squareLightOverGround(Emitter::Shape), 32, 256, 31, 2).radiance, 1).mean;
        const double mesh = channelStats(render(squareLightOverGround(Emitter::MeshDoubleSided), 32, 256, 31, 2).radiance, 1).mean;
        QVERIFY2(std::abs(mesh - shape) < 0.02 * shape, qPrintable(QString("mesh %1, shape %2").arg(mesh).arg(shape)));
    }

    // Same scene and settings. A single-sided emitter lights only what its front faces: turned down
    // (by a rotation, or by a mirroring scale) it gives the double-sided image (everything the
    // camera and the ground see is below it), means within 2 %; with its front up the ground and
    // the camera get nothing from it (its back face is black: albedo 0), mean exactly 0. Light
    // sampling and BSDF-sampled hits must agree on the side, or the MIS weights no longer sum to 1.
    void singleSidedEmitterLightsItsFrontOnly() {
        const double both = channelStats(render(squareLightOverGround(Emitter::MeshDoubleSided), 32, 256, 31, 2).radiance, 1).mean;
        for (const Emitter e : {Emitter::MeshFrontDown, Emitter::MeshFrontDownMirrored}) {
            const double front = channelStats(render(squareLightOverGround(e), 32, 256, 31, 2).radiance, 1).mean;
            QVERIFY2(std::abs(front - both) < 0.02 * both, qPrintable(QString("front down %1, double-sided %2").arg(front).arg(both)));
        }
        const double up = channelStats(render(squareLightOverGround(Emitter::MeshFrontUp), 32, 256, 31, 2).radiance, 1).mean;
        QCOMPARE(up, 0.0);
    }

    // 32x32, 16 spp, seed 32, 2 bounces. A 12-triangle box mesh and the analytic box it tessellates,
    // under a sun on a ground plane: image means within 1 %; object ids equal but on edges (< 3 %).
    void boxMeshMatchesAnalyticBox() {
        const auto scene = [](bool asMesh) {
            Scene s;
            const MaterialId grey = s.materials.add(lambert(glm::vec3(0.6f)));
            const MaterialId red = s.materials.add(lambert({0.7f, 0.1f, 0.1f}));
            addShape(s, ShapeKind::GroundPlane, grey, glm::vec3(0.0f));
            Node box;
            box.name = "box";
            box.local.translation = {0.0f, 0.5f, 0.0f};
            box.local.rotation = glm::angleAxis(0.5f, glm::vec3(0.0f, 1.0f, 0.0f));
            if (asMesh) {
                box.component = MeshInstance{s.meshes.add(boxMesh(glm::vec3(1.0f), red))};
            } else {
                Shape shape;
                shape.kind = ShapeKind::Box;
                shape.material = red;
                box.component = shape;
            }
            s.addNode(box);
            addSun(s, {0.4f, -1.0f, -0.3f}, 1000.0f);
            addPerspectiveCamera(s, {0.0f, 1.5f, 3.0f}, {0.0f, 0.4f, 0.0f}, 0.8f);
            return s;
        };
        const auto mesh = render(scene(true), 32, 16, 32, 2);
        const auto shape = render(scene(false), 32, 16, 32, 2);
        const double meshMean = channelStats(mesh.radiance, 0).mean, shapeMean = channelStats(shape.radiance, 0).mean;
        QVERIFY2(std::abs(meshMean - shapeMean) < 0.01 * shapeMean, qPrintable(QString("%1 vs %2").arg(meshMean).arg(shapeMean)));
        int differentIds = 0;
        for (std::size_t i = 0; i < mesh.objectId.size(); ++i) differentIds += mesh.objectId[i] != shape.objectId[i];
        QVERIFY2(differentIds < 31, qPrintable(QString("%1 ids differ").arg(differentIds)));
        QCOMPARE(mesh.objectId[16 * 32 + 16], 2.0f); // the box node, in front of the ground (node 1)
    }

    // 32x32, 8 spp, seed 33: zero-area and repeated-vertex triangles, NaN and zero vertex normals.
    void degenerateTrianglesStayFinite() {
        Scene scene;
        const MaterialId grey = scene.materials.add(lambert(glm::vec3(0.6f)));
        Mesh mesh = quadMesh(1.0f, grey);
        Primitive& p = mesh.primitives[0];
        p.normals[1] = glm::vec3(0.0f);
        p.normals[2] = glm::vec3(std::nanf(""));
        p.positions.push_back({0.2f, 0.0f, 0.2f});
        p.normals.push_back(glm::vec3(0.0f));
        p.indices.insert(p.indices.end(), {4, 4, 4, 0, 2, 0, 0, 4, 2});
        addMeshNode(scene, scene.meshes.add(std::move(mesh)), glm::vec3(0.0f));
        addSun(scene, {0.0f, -1.0f, 0.2f}, 1000.0f);
        addPerspectiveCamera(scene, {0.0f, 1.0f, 1.0f}, glm::vec3(0.0f), 1.0f);
        const auto out = render(scene, 32, 8, 33, 3);
        for (std::size_t i = 0; i < out.radiance.size(); ++i)
            QVERIFY2(std::isfinite(out.radiance[i]) && out.radiance[i] >= 0.0f, qPrintable(QString("value %1 = %2").arg(i).arg(out.radiance[i])));
        QVERIFY(channelStats(out.radiance, 0).maximum > 0.0);
    }

    // 64x64, 16 spp, seed 0, 4 bounces: the Cornell box from resources/. Every pixel finite and
    // non-negative, the image lit (mean radiance > 0.01), the centre pixel on an object; the PNG goes
    // to the temp dir for a person to look at.
    void cornellBoxRenders() {
        const auto loaded = loadScene(std::filesystem::path(GLINT_RESOURCES_DIR) / "scenes" / "cornell_box" / "cornell_box.gltf");
        const auto out = render(loaded.scene, 64, 16, 0, 4);
        for (std::size_t i = 0; i < out.radiance.size(); ++i)
            QVERIFY2(std::isfinite(out.radiance[i]) && out.radiance[i] >= 0.0f, qPrintable(QString("value %1").arg(i)));
        QVERIFY2(channelStats(out.radiance, 1).mean > 0.01, qPrintable(QString("mean %1").arg(channelStats(out.radiance, 1).mean)));
        QVERIFY(out.objectId[32 * 64 + 32] > 0.0f);
        QTemporaryDir dir;
        dir.setAutoRemove(false);
        const std::string png = dir.filePath("cornell_box.png").toStdString();
        auto file = OIIO::ImageOutput::create(png);
        QVERIFY(file && file->open(png, OIIO::ImageSpec(64, 64, 4, OIIO::TypeDesc::UINT8)));
        QVERIFY(file->write_image(OIIO::TypeDesc::UINT8, out.tonemapped.data()));
        file->close();
        qInfo("Cornell box: %s (%.1f ms per sample on %s)", png.c_str(), out.timings.msPerSample, out.glRenderer.c_str());
    }
};

QTEST_APPLESS_MAIN(TestRenderMeshes)
#include "test_render_meshes.moc"
