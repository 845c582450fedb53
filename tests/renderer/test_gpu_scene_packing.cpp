// The CPU side of the GPU scene, without a GL context: light units, material and shape packing,
// camera resolution by name, the emissive-triangle distribution, and the emitters light sampling
// leaves out.
#include "mesh_builder.h"
#include "scene_builder.h"

#include "renderer/gpu_scene/camera_setup.h"
#include "renderer/gpu_scene/emissive_triangles.h"
#include "renderer/gpu_scene/light_units.h"
#include "renderer/gpu_scene/packed_scene.h"
#include "renderer/gpu_scene/prepared_scene.h"
#include "renderer/gpu_scene/texture_set.h"

#include <QTest>

#include <cmath>

using namespace glint;
using namespace glint::test;

class TestGpuScenePacking : public QObject {
    Q_OBJECT
private slots:
    // Blender mode: lux/683 and cd/683; raw mode: as is. Colour multiplies.
    void lightUnitsFollowBlenderOrRaw() {
        Light sun;
        sun.type = LightType::Sun;
        sun.intensity = 683.0f;
        sun.color = {1.0f, 0.5f, 0.25f};
        QCOMPARE(renderer::radiometricIntensity(sun, LightUnits::Blender), glm::vec3(1.0f, 0.5f, 0.25f));
        QCOMPARE(renderer::radiometricIntensity(sun, LightUnits::Raw), glm::vec3(683.0f, 341.5f, 170.75f));
    }

    // Emission is factor x strength, 1:1; a material without volume thickness is thin-walled (0);
    // an infinite attenuation distance means no absorption (0).
    void materialTexels() {
        Material m;
        m.baseColorFactor = {0.1f, 0.2f, 0.3f, 0.4f};
        m.emissiveFactor = {1.0f, 2.0f, 3.0f};
        m.emissiveStrength = 10.0f;
        m.roughnessFactor = 0.25f;
        m.metallicFactor = 0.5f;
        m.specularFactor = 0.0f;
        m.transmissionFactor = 1.0f;
        m.ior = 1.33f;
        const auto texels = renderer::packMaterial(m);
        QCOMPARE(int(texels.size()), renderer::materialTexels);
        QCOMPARE(texels[0], glm::vec4(0.1f, 0.2f, 0.3f, 0.4f));
        QCOMPARE(texels[1], glm::vec4(10.0f, 20.0f, 30.0f, 0.25f));
        QCOMPARE(texels[2], glm::vec4(0.5f, 0.0f, 1.0f, 1.33f));
        QCOMPARE(texels[3].w, 0.0f);
        QCOMPARE(texels[4].w, 0.0f);
    }

    // Index 0 is glTF's default material; shapes carry kind, material index, node id and their
    // localFromWorld rows; invisible subtrees are left out; lights point along their node's -Z.
    void shapesAndLights() {
        Scene scene;
        const MaterialId red = scene.materials.add(lambert({1.0f, 0.0f, 0.0f}));
        const NodeId sphere = addShape(scene, ShapeKind::Sphere, red, {1.0f, 2.0f, 3.0f});
        const NodeId hidden = addShape(scene, ShapeKind::Box, red, glm::vec3(0.0f));
        scene.setVisible(hidden, false);
        addSun(scene, {0.0f, -1.0f, 0.0f}, 683.0f);
        const auto packed = renderer::packScene(scene);
        QCOMPARE(packed.shapeCount, 1);
        QCOMPARE(packed.materialIndex.at(red), 1);
        QCOMPARE(packed.shapes[0], glm::vec4(0.0f, 1.0f, float(sphere.value), 1.0f));
        QCOMPARE(packed.shapes[1], glm::vec4(1.0f, 0.0f, 0.0f, -1.0f)); // x_local = x_world - 1
        QCOMPARE(packed.lightCount, 1);
        QCOMPARE(packed.lights[1], glm::vec4(1.0f, 1.0f, 1.0f, 1.0f)); // 1 W/m^2, delta sun (cos 0 = 1)
        QVERIFY(glm::length(glm::vec3(packed.lights[3]) - glm::vec3(0.0f, -1.0f, 0.0f)) < 1e-6f);
    }

    // By node name; otherwise the active camera, else the first; an unknown name is an error.
    void camerasResolveByName() {
        Scene scene;
        addPerspectiveCamera(scene, glm::vec3(0.0f), {0.0f, 0.0f, -1.0f}, 1.0f);
        const NodeId second = addOrthographicCamera(scene, {0.0f, 5.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 2.0f);
        scene.setName(second, "top");
        const auto top = renderer::resolveCamera(scene, "top", 200, 100);
        QVERIFY(top.orthographic);
        QCOMPARE(top.halfExtent, glm::vec2(4.0f, 2.0f));
        const auto first = renderer::resolveCamera(scene, "", 100, 100);
        QVERIFY(!first.orthographic);
        QCOMPARE(first.halfExtent.y, float(std::tan(0.5)));
        scene.settings.activeCamera = second;
        QVERIFY(renderer::resolveCamera(scene, "", 100, 100).orthographic);
        try {
            renderer::resolveCamera(scene, "missing", 10, 10);
            QFAIL("no exception");
        } catch (const std::runtime_error& e) {
            QCOMPARE(QString(e.what()), QString("no camera named \"missing\""));
        }
    }

    // The CDF follows area x luminance; zero-area and black triangles are never chosen.
    void emissiveTrianglesByPower() {
        renderer::EmissiveTriangles lights;
        lights.add({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, glm::vec3(1.0f));   // area 0.5, power 0.5
        lights.add({0, 0, 0}, {1, 0, 0}, {2, 0, 0}, glm::vec3(5.0f));   // zero area: skipped
        lights.add({0, 0, 0}, {2, 0, 0}, {0, 1, 0}, glm::vec3(0.0f));   // black: skipped
        lights.add({0, 0, 0}, {2, 0, 0}, {0, 1, 0}, glm::vec3(1.5f));   // area 1, power 1.5
        lights.finish();
        QCOMPARE(lights.count(), 2);
        QCOMPARE(lights.totalPower, 2.0f);
        QCOMPARE(lights.cdf, (std::vector<float>{0.0f, 0.25f, 1.0f}));
        QCOMPARE(lights.texels.size(), 2 * renderer::EmissiveTriangles::texelsPerTriangle);
        QCOMPARE(lights.texels[4], glm::vec4(0.0f)); // untextured: no slot
        // A textured one names its slot exactly, beyond 2^24 too, and whether p1 and p2 were swapped.
        const std::uint32_t slot = (1u << 24) + 3u;
        lights.add({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, glm::vec3(1.0f), true, renderer::EmitterTexturing{slot, true});
        QCOMPARE(lights.texels.back(), glm::vec4(float(slot >> 16), 3.0f, 1.0f, 1.0f));
        QCOMPARE(std::uint32_t(lights.texels.back().x) * 65536u + std::uint32_t(lights.texels.back().y), slot);
    }

    // Emitters that light sampling leaves to BSDF-sampled rays, which keep a path from ending at its
    // last vertex's light samples: an emissive ground plane, an emissive-textured shape, an
    // emissive-textured mesh material whose texture has no mean. An emissive sphere and an emissive
    // mesh, textured with a mean or not, are light-sampled.
    void unsampledEmittersAreFound() {
        const auto base = [](Scene& scene, MaterialId& glow, MaterialId& texturedGlow, ImageId& image) {
            glow = scene.materials.add(lambert(glm::vec3(0.0f), glm::vec3(1.0f)));
            Texture texture;
            image = texture.image = scene.images.add(Image{});
            Material textured = lambert(glm::vec3(0.0f), glm::vec3(1.0f));
            textured.emissiveTexture.texture = scene.textures.add(std::move(texture));
            texturedGlow = scene.materials.add(std::move(textured));
            addShape(scene, ShapeKind::Sphere, glow, glm::vec3(0.0f));
            addNode(scene, "lamp", MeshInstance{scene.meshes.add(quadMesh(1.0f, glow))}, glm::vec3(0.0f));
        };
        MaterialId glow, texturedGlow;
        ImageId image;
        Scene lit;
        base(lit, glow, texturedGlow, image);
        QVERIFY(!renderer::hasUnsampledEmitters(lit, nullptr));

        Scene ground;
        base(ground, glow, texturedGlow, image);
        addShape(ground, ShapeKind::GroundPlane, glow, glm::vec3(0.0f));
        QVERIFY(renderer::hasUnsampledEmitters(ground, nullptr));

        Scene texturedShape;
        base(texturedShape, glow, texturedGlow, image);
        addShape(texturedShape, ShapeKind::Box, texturedGlow, glm::vec3(0.0f));
        QVERIFY(renderer::hasUnsampledEmitters(texturedShape, nullptr));

        Scene texturedMesh;
        base(texturedMesh, glow, texturedGlow, image);
        addNode(texturedMesh, "textured lamp", MeshInstance{texturedMesh.meshes.add(quadMesh(1.0f, texturedGlow))}, glm::vec3(0.0f));
        renderer::TextureSet textures;
        QVERIFY(renderer::hasUnsampledEmitters(texturedMesh, &textures));
        textures.meanOf[{image, true}] = glm::vec3(0.5f);
        QVERIFY(!renderer::hasUnsampledEmitters(texturedMesh, &textures));
    }
};

QTEST_APPLESS_MAIN(TestGpuScenePacking)
#include "test_gpu_scene_packing.moc"
