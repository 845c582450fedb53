// What a camera-less render falls back to: the world box around what a scene draws, the default
// view that frames it, and whether anything in the scene emits light.
#include "scene/core/default_view.h"
#include "scene/core/light_sources.h"
#include "scene/core/scene_bounds.h"

#include <QtTest>

#include <glm/gtc/quaternion.hpp>

#include <cmath>

using namespace glint;

namespace {

NodeId addShape(Scene& scene, Shape shape, glm::vec3 translation, NodeId parent = {}) {
    Node node;
    node.local.translation = translation;
    node.component = shape;
    return scene.addNode(std::move(node), parent);
}

Shape box(glm::vec3 size) {
    Shape s;
    s.kind = ShapeKind::Box;
    s.size = size;
    return s;
}

bool near(glm::vec3 a, glm::vec3 b) { return glm::length(a - b) < 1e-4f; }

// Where a world point lands in the default camera's image, in [-1, 1] on each axis when inside.
glm::vec2 ndc(const Scene& scene, NodeId cameraNode, glm::vec3 world, float aspect) {
    const Camera& camera = *scene.node(cameraNode)->get<Camera>();
    const glm::vec3 p(glm::inverse(scene.worldFromNode(cameraNode)) * glm::vec4(world, 1.0f));
    const float tanHalf = std::tan(0.5f * camera.yfov);
    return {p.x / (-p.z * tanHalf * aspect), p.y / (-p.z * tanHalf)};
}

} // namespace

class TestSceneFraming : public QObject {
    Q_OBJECT
private slots:
    void boundsCoverMeshesAndShapesInWorldSpace() {
        Scene scene;
        const NodeId parent = addShape(scene, box({2, 2, 2}), {10, 0, 0});
        addShape(scene, box({1, 4, 1}), {0, 1, 0}, parent); // child at (10, 1, 0), y from -1 to 3
        Mesh mesh;
        mesh.primitives.emplace_back().positions = {{-1, 0, 0}, {0, 0, -3}, {0, 0, 0}};
        Node meshNode;
        meshNode.local.translation = {0, 0, -1};
        meshNode.component = MeshInstance{scene.meshes.add(mesh)};
        scene.addNode(std::move(meshNode));

        const Bounds bounds = worldBounds(scene);
        QVERIFY(near(bounds.min, {-1, -1, -4}));
        QVERIFY(near(bounds.max, {11, 3, 1}));
    }

    void boundsLeaveOutHiddenNodesGroundPlanesLightsAndNonFinitePositions() {
        Scene scene;
        addShape(scene, box({1, 1, 1}), {0, 0, 0});
        const NodeId hidden = addShape(scene, box({1, 1, 1}), {100, 0, 0});
        scene.setVisible(hidden, false);
        Shape ground;
        ground.kind = ShapeKind::GroundPlane;
        addShape(scene, ground, {0, -50, 0});
        Node light;
        light.local.translation = {0, 40, 0};
        light.component = Light{};
        scene.addNode(std::move(light));
        Mesh broken;
        broken.primitives.emplace_back().positions = {{NAN, 0, 0}, {0, INFINITY, 0}, {0.25f, 0.25f, 0.25f}};
        Node brokenNode;
        brokenNode.component = MeshInstance{scene.meshes.add(broken)};
        scene.addNode(std::move(brokenNode));

        const Bounds bounds = worldBounds(scene);
        QVERIFY(near(bounds.min, {-0.5f, -0.5f, -0.5f}));
        QVERIFY(near(bounds.max, {0.5f, 0.5f, 0.5f}));
        QVERIFY(worldBounds(Scene{}).empty());
    }

    void defaultViewLooksAtTheCentreAndFitsEveryCorner_data() {
        QTest::addColumn<float>("aspect");
        QTest::newRow("square") << 1.0f;
        QTest::newRow("wide") << 2.0f;
        QTest::newRow("tall") << 0.5f;
    }

    void defaultViewLooksAtTheCentreAndFitsEveryCorner() {
        QFETCH(float, aspect);
        Scene scene;
        addShape(scene, box({4, 1, 2}), {3, 2, 1});
        const NodeId view = addDefaultView(scene, aspect);
        QCOMPARE(scene.settings.activeCamera, view);
        QCOMPARE(scene.node(view)->name, std::string(kDefaultViewName));
        const glm::mat4 world = scene.worldFromNode(view);
        const glm::vec3 eye(world[3]), forward = -glm::normalize(glm::vec3(world[2]));
        const glm::vec3 centre(3, 2, 1);
        QVERIFY(near(glm::normalize(centre - eye), forward));                   // aims at the centre
        QVERIFY(eye.z > centre.z && eye.y > centre.y && near({eye.x, 0, 0}, {3, 0, 0})); // front, above
        QVERIFY(std::abs(glm::vec3(world[0]).y) < 1e-5f);                       // no roll: +Y stays up
        float widest = 0.0f;
        for (int c = 0; c < 8; ++c) {
            const glm::vec3 corner(c & 1 ? 5 : 1, c & 2 ? 2.5f : 1.5f, c & 4 ? 2 : 0);
            const glm::vec2 p = ndc(scene, view, corner, aspect);
            widest = std::max({widest, std::abs(p.x), std::abs(p.y)});
        }
        QVERIFY2(widest < 1.0f, qPrintable(QString::number(widest)));
        QVERIFY2(widest > 0.4f, qPrintable(QString::number(widest))); // framed, not a speck
        QVERIFY(std::abs(scene.node(view)->get<Camera>()->focusDistance - glm::length(centre - eye)) < 1e-4f);
    }

    void emptySceneIsSeenFromFiveMetres() {
        Scene scene;
        const NodeId view = addDefaultView(scene, 1.5f);
        QVERIFY(std::abs(glm::length(glm::vec3(scene.worldFromNode(view)[3])) - 5.0f) < 1e-5f);
    }

    void lightSourcesAreLightsEmittersAndTheEnvironment() {
        Scene dark;
        addShape(dark, box({1, 1, 1}), {});
        QCOMPARE(sceneLighting(dark), SceneLighting::None);

        const auto addSun = [](Scene& scene) {
            Node sun;
            sun.component = Light{.type = LightType::Sun, .intensity = 3.0f};
            scene.addNode(std::move(sun));
        };
        Scene lit = dark;
        addSun(lit);
        QCOMPARE(sceneLighting(lit), SceneLighting::Lit);

        Scene glowing = dark;
        Material glow;
        glow.emissiveFactor = {0, 0.5f, 0};
        Shape lamp = box({1, 1, 1});
        lamp.material = glowing.materials.add(glow);
        const NodeId lampNode = addShape(glowing, lamp, {});
        QCOMPARE(sceneLighting(glowing), SceneLighting::Lit);
        glowing.setVisible(lampNode, false);
        QCOMPARE(sceneLighting(glowing), SceneLighting::None);

        // Emission through a texture at glTF's default strength is a glowing detail: the scene is
        // lit by emissive textures only until a light, an untextured emitter or a raised strength
        // (KHR_materials_emissive_strength above 1) joins it.
        Scene label = dark;
        Material printed;
        printed.emissiveFactor = {1, 1, 1};
        printed.emissiveTexture.texture = label.textures.add(Texture{});
        Shape bottle = box({1, 1, 1});
        bottle.material = label.materials.add(printed);
        addShape(label, bottle, {});
        QCOMPARE(sceneLighting(label), SceneLighting::EmissiveTexturesOnly);
        Scene brightLabel = label;
        brightLabel.materials.at(bottle.material).emissiveStrength = 4.0f;
        QCOMPARE(sceneLighting(brightLabel), SceneLighting::Lit);
        Scene labelAndLamp = label;
        Shape lampToo = box({1, 1, 1});
        lampToo.material = labelAndLamp.materials.add(glow);
        addShape(labelAndLamp, lampToo, {});
        QCOMPARE(sceneLighting(labelAndLamp), SceneLighting::Lit);
        Scene labelUnderSun = label;
        addSun(labelUnderSun);
        QCOMPARE(sceneLighting(labelUnderSun), SceneLighting::Lit);

        Scene sky = dark;
        sky.settings.environment.color = {0.1f, 0.1f, 0.1f};
        QCOMPARE(sceneLighting(sky), SceneLighting::Lit);
        sky.settings.environment.intensity = 0.0f;
        QCOMPARE(sceneLighting(sky), SceneLighting::None);
    }
};

QTEST_APPLESS_MAIN(TestSceneFraming)
#include "test_scene_framing.moc"
