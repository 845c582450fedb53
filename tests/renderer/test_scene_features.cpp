// Which shader variant a scene gets (SceneFeatures::defines): each feature is compiled in exactly
// when the scene uses it. Without a GL context: the preparation is CPU work. A feature left in
// where it is not used costs time on llvmpipe (docs/PERFORMANCE.md, "Every branch costs"); one left
// out where it is used renders wrongly, which the render tests of each feature would show.
#include "scene_builder.h"

#include "renderer/gpu_scene/prepared_scene.h"
#include "scene/io/scene_io.h"

#include <QTest>

using namespace glint;
using namespace glint::test;

namespace {

std::map<std::string, std::string> definesOf(const Scene& scene) {
    renderer::MeshBvhCache cache;
    return renderer::prepareScene(scene, {}, renderer::TextureLimits{}, cache).features.defines();
}

bool has(const std::map<std::string, std::string>& defines, const char* name) { return defines.contains(name); }

Scene shapesLitBySun() {
    Scene scene;
    const MaterialId grey = scene.materials.add(lambert(glm::vec3(0.5f)));
    addShape(scene, ShapeKind::Sphere, grey, {0.0f, 0.0f, 0.0f});
    addSun(scene, {0.0f, -1.0f, 0.0f}, 1000.0f);
    return scene;
}

} // namespace

class TestSceneFeatures : public QObject {
    Q_OBJECT
private slots:
    // The bundled Cornell box: meshes of single-sided materials and an emissive ceiling, nothing else.
    void meshOnlySceneLeavesOutShapesLightsAndGlass() {
        const Scene scene = loadScene(GLINT_RESOURCES_DIR "/scenes/cornell_box/cornell_box.gltf").scene;
        const auto defines = definesOf(scene);
        QVERIFY(has(defines, "HAS_MESHES"));
        QVERIFY(has(defines, "HAS_SINGLE_SIDED"));
        QVERIFY(has(defines, "HAS_AREA_EMITTERS")); // the emissive ceiling triangles
        for (const char* absent : {"HAS_SHAPES", "HAS_PUNCTUAL_LIGHTS", "HAS_TRANSMISSION", "HAS_ENV_MAP", "HAS_EMISSIVE_SHAPES"})
            QVERIFY2(!has(defines, absent), absent);
    }

    // With its ceiling switched off no triangle emits: no area light sample per vertex.
    void meshesWithoutEmissionLeaveOutTheAreaSample() {
        Scene scene = loadScene(GLINT_RESOURCES_DIR "/scenes/cornell_box/cornell_box.gltf").scene;
        for (auto& [id, material] : scene.materials) material.emissiveFactor = glm::vec3(0.0f);
        QVERIFY(!has(definesOf(scene), "HAS_AREA_EMITTERS"));
    }

    void shapesAndSunAreCompiledIn() {
        const auto defines = definesOf(shapesLitBySun());
        QVERIFY(has(defines, "HAS_SHAPES"));
        QVERIFY(has(defines, "HAS_PUNCTUAL_LIGHTS"));
        QVERIFY(!has(defines, "HAS_MESHES"));
        QVERIFY(!has(defines, "HAS_AREA_EMITTERS")); // nothing emits but the sun
        QVERIFY(!has(defines, "HAS_TRANSMISSION"));
    }

    // One transmissive material anywhere in the scene brings the BSDF's glass lobe in.
    void glassBringsTheTransmissionLobe() {
        Scene scene = shapesLitBySun();
        const MaterialId glassy = scene.materials.add(glass(1.5f, 0.0f));
        addShape(scene, ShapeKind::Sphere, glassy, {1.5f, 0.0f, 0.0f});
        QVERIFY(has(definesOf(scene), "HAS_TRANSMISSION"));

        Material barely = lambert(glm::vec3(0.5f));
        barely.transmissionFactor = 0.01f;
        Scene other = shapesLitBySun();
        addShape(other, ShapeKind::Box, other.materials.add(barely), {0.0f, 2.0f, 0.0f});
        QVERIFY(has(definesOf(other), "HAS_TRANSMISSION"));
    }

    // An area light is a shape of its own: the shape code comes with it.
    void areaLightBringsShapes() {
        Scene scene;
        Light panel;
        panel.type = LightType::Area;
        panel.intensity = 10.0f;
        addNode(scene, "panel", panel, {0.0f, 1.0f, 0.0f});
        const auto defines = definesOf(scene);
        QVERIFY(has(defines, "HAS_SHAPES"));
        QVERIFY(has(defines, "HAS_EMISSIVE_SHAPES"));
        QVERIFY(has(defines, "HAS_AREA_EMITTERS"));
        QVERIFY(!has(defines, "HAS_PUNCTUAL_LIGHTS"));
    }
};

QTEST_APPLESS_MAIN(TestSceneFeatures)
#include "test_scene_features.moc"
