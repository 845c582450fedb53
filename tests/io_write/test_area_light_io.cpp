// Area lights in glTF: GLINT_area_light on the node carries the light, and the node's mesh, an
// emissive fallback with KHR_materials_emissive_strength, is what other viewers show. Saved and
// loaded back the scene is equal (no fallback mesh or material stays behind), a second save is
// byte-identical, the emission written is the light's radiance P / (pi A) x colour, and the files
// pass the Khronos validator with 0 errors (not in sanitizer builds, which have no validator).
#include "io_write_helpers.h"
#ifdef GLINT_VALIDATE_OUTPUT
#include "validator_run.h"
#endif

#include "scene/core/area_light.h"
#include "scene/io/scene_io.h"

#include <glm/gtc/quaternion.hpp>

#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>

using namespace glint;
namespace fs = std::filesystem;

namespace {

Node lightNode(const std::string& name, const Light& light, Transform local)
{
    Node node;
    node.name = name;
    node.local = local;
    node.component = light;
    return node;
}

Light areaLight(AreaShape shape, float watts, glm::vec3 colour, glm::vec2 size, float radius)
{
    Light light;
    light.type = LightType::Area;
    light.areaShape = shape;
    light.intensity = watts;
    light.color = colour;
    light.size = size;
    light.radius = radius;
    return light;
}

// A rectangle turned to face down, a disk under a scaled parent, a sphere, beside an ordinary
// material on a shape (so that the fallback materials follow the scene's).
Scene areaLightScene()
{
    Scene scene;
    Material plastic;
    plastic.name = "plastic";
    plastic.baseColorFactor = {0.8f, 0.2f, 0.1f, 1.0f};
    const MaterialId material = scene.materials.add(plastic);
    Node ball;
    ball.name = "ball";
    Shape sphere;
    sphere.material = material;
    ball.component = sphere;
    scene.addNode(std::move(ball));
    Transform down;
    down.translation = {0.0f, 2.0f, 0.0f};
    down.rotation = glm::angleAxis(-0.5f * std::numbers::pi_v<float>, glm::vec3(1.0f, 0.0f, 0.0f));
    scene.addNode(lightNode("panel", areaLight(AreaShape::Rectangle, 40.0f, {1.0f, 0.9f, 0.8f}, {1.5f, 0.5f}, 0.0f), down));
    Node group;
    group.name = "rig";
    group.local.scale = glm::vec3(2.0f);
    const NodeId rig = scene.addNode(std::move(group));
    Transform side;
    side.translation = {1.0f, 1.0f, 0.0f};
    scene.addNode(lightNode("softbox", areaLight(AreaShape::Disk, 25.0f, {0.5f, 0.7f, 1.0f}, {0.6f, 0.6f}, 0.0f), side), rig);
    Transform lamp;
    lamp.translation = {-1.0f, 1.5f, 0.5f};
    scene.addNode(lightNode("bulb", areaLight(AreaShape::Sphere, 60.0f, glm::vec3(1.0f), {1.0f, 1.0f}, 0.05f), lamp));
    return scene;
}

const nlohmann::json* nodeNamed(const nlohmann::json& root, const std::string& name)
{
    for (const auto& node : root["nodes"])
        if (node.value("name", "") == name) return &node;
    return nullptr;
}

} // namespace

class TestAreaLightIo : public QObject {
    Q_OBJECT

private slots:
    void roundTripIsLossless_data()
    {
        QTest::addColumn<QString>("format");
        QTest::newRow("gltf") << QString(".gltf");
        QTest::newRow("glb") << QString(".glb");
    }

    void roundTripIsLossless()
    {
        QFETCH(QString, format);
        const Scene scene = areaLightScene();
        QTemporaryDir first, second;
        const fs::path saved = fs::path(first.path().toStdString()) / ("lights" + format.toStdString());
        saveScene(scene, saved);
        const LoadResult loaded = loadScene(saved);
        for (const Warning& w : loaded.warnings) QVERIFY2(false, (w.code + ": " + w.message).c_str());
        QVERIFY2(loaded.scene.nodes() == scene.nodes(), "nodes differ after loading");
        QVERIFY2(loaded.scene.materials == scene.materials, "materials differ after loading (a fallback material stayed?)");
        QVERIFY2(loaded.scene.meshes == scene.meshes, "meshes differ after loading (a fallback mesh stayed?)");
        QVERIFY2(loaded.scene == scene, "the scene differs after loading");
        const fs::path again = fs::path(second.path().toStdString()) / ("lights" + format.toStdString());
        saveScene(loaded.scene, again);
        QVERIFY2(test::readBytes(saved) == test::readBytes(again), "the second save differs");
#ifdef GLINT_VALIDATE_OUTPUT
        const std::string errors = test::validatorErrors({saved});
        QVERIFY2(errors.empty(), errors.c_str());
#endif
    }

    // What other viewers read: each area light node has a mesh whose one primitive's material is
    // black and emits emissiveFactor x emissiveStrength = P / (pi A) x colour, A the world area
    // (the disk's parent scales it by 2), with emissiveFactor at most 1 and both extensions declared.
    void fallbackEmitsTheLightsRadiance()
    {
        const Scene scene = areaLightScene();
        QTemporaryDir dir;
        const fs::path saved = fs::path(dir.path().toStdString()) / "lights.gltf";
        saveScene(scene, saved);
        const nlohmann::json root = nlohmann::json::parse(test::readText(saved));
        const auto used = root["extensionsUsed"].get<std::vector<std::string>>();
        for (const char* name : {"GLINT_area_light", "KHR_materials_emissive_strength"})
            QVERIFY2(std::find(used.begin(), used.end(), name) != used.end(), name);
        for (const auto& [name, area] : {std::pair<std::string, double>{"panel", 1.5 * 0.5},
                                         {"softbox", std::numbers::pi * 0.6 * 0.6},     // diameter 0.6 x 2
                                         {"bulb", 4.0 * std::numbers::pi * 0.05 * 0.05}}) {
            const nlohmann::json* node = nodeNamed(root, name);
            QVERIFY2(node && node->contains("mesh") && (*node)["extensions"].contains("GLINT_area_light"), name.c_str());
            const Light& light = *scene.at(*scene.findByName(name)).get<Light>();
            QVERIFY(std::abs(areaLightArea(light, scene.worldFromNode(*scene.findByName(name))) / area - 1.0) < 1e-4);
            const auto& primitive = root["meshes"][(*node)["mesh"].get<std::size_t>()]["primitives"][0];
            const auto& material = root["materials"][primitive["material"].get<std::size_t>()];
            const auto factor = material["emissiveFactor"].get<std::vector<double>>();
            const double strength = material["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"].get<double>();
            QCOMPARE(*std::max_element(factor.begin(), factor.end()), 1.0);
            for (int c = 0; c < 3; ++c) {
                const double expected = light.intensity / (std::numbers::pi * area) * light.color[c];
                QVERIFY2(std::abs(factor[std::size_t(c)] * strength / expected - 1.0) < 1e-5,
                         qPrintable(QString("%1 channel %2: %3 vs %4").arg(name.c_str()).arg(c).arg(factor[std::size_t(c)] * strength).arg(expected)));
            }
            QCOMPARE(material["pbrMetallicRoughness"]["baseColorFactor"][0].get<double>(), 0.0);
        }
    }

    // A hand-written GLINT_area_light: a negative power is clamped to 0 and named; an unknown shape is refused.
    void badValuesAreNamed()
    {
        QTemporaryDir dir;
        const fs::path file = fs::path(dir.path().toStdString()) / "bad.gltf";
        const auto write = [&](const std::string& ext) {
            std::ofstream(file) << R"({"asset": {"version": "2.0"}, "extensionsUsed": ["GLINT_area_light"], "scenes": [{"nodes": [0]}],)"
                                   R"("nodes": [{"name": "l", "extensions": {"GLINT_area_light": )" + ext + "}}]}";
        };
        write(R"({"shape": "disk", "power": -3, "size": [0.5, 0.5]})");
        const LoadResult loaded = loadScene(file);
        const Light* light = loaded.scene.at(*loaded.scene.findByName("l")).get<Light>();
        QVERIFY(light && light->type == LightType::Area && light->areaShape == AreaShape::Disk);
        QCOMPARE(light->intensity, 0.0f);
        QCOMPARE(light->size.x, 0.5f);
        bool named = false;
        for (const Warning& w : loaded.warnings) named = named || (w.code == "invalid-value" && w.message.find("power") != std::string::npos);
        QVERIFY(named);
        write(R"({"shape": "triangle", "power": 3})");
        bool refused = false;
        try {
            loadScene(file);
        } catch (const std::exception& e) {
            refused = std::string(e.what()).find("triangle") != std::string::npos;
        }
        QVERIFY(refused);
    }
};

QTEST_APPLESS_MAIN(TestAreaLightIo)
#include "test_area_light_io.moc"
