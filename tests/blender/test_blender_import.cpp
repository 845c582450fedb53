// Blender opens what Glint writes: the feature scene (shapes, every light kind, cameras, materials,
// node animations) saved as .gltf is imported by Blender's own glTF importer in a background
// Blender, and what arrives is counted (tests/blender/import_counts.py): one object per node,
// one light per punctual light node, one camera per camera node, the materials the scene uses, a
// mesh per shape, objects with an emitting material (area lights included) as emitters, and the animated nodes animated.
#include "../io_write/feature_scene.h"

#include "scene/io/scene_io.h"

#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <nlohmann/json.hpp>

#include <set>

using namespace glint;

namespace {

struct Expected {
    int objects = 0, lights = 0, cameras = 0, shapes = 0, meshInstances = 0, emissive = 0;
    int areaLights = 0; // each written with a mesh and an emissive material of its own
    std::set<MaterialId> materials;
    std::set<NodeId> animated;
};

bool emits(const Scene& scene, MaterialId id) {
    const Material* m = scene.materials.find(id);
    return m && glm::length(m->emissiveFactor) > 0.0f && m->emissiveStrength > 0.0f;
}

Expected expectedOf(const Scene& scene) {
    Expected e;
    for (const auto& [id, node] : scene.nodes()) {
        ++e.objects;
        if (const Light* light = node.get<Light>()) {
            if (light->type == LightType::Area) {
                ++e.emissive;
                ++e.areaLights;
            } else {
                ++e.lights;
            }
        }
        if (node.get<Camera>()) ++e.cameras;
        if (const Shape* shape = node.get<Shape>()) {
            ++e.shapes;
            if (shape->material.valid()) e.materials.insert(shape->material);
            if (emits(scene, shape->material)) ++e.emissive;
        }
        if (const MeshInstance* instance = node.get<MeshInstance>()) {
            ++e.meshInstances;
            bool emissive = false;
            for (const Primitive& p : scene.meshes.at(instance->mesh).primitives) {
                if (p.material.valid()) e.materials.insert(p.material);
                emissive = emissive || emits(scene, p.material);
            }
            if (emissive) ++e.emissive;
        }
    }
    for (const auto& [id, animation] : scene.animations)
        for (const AnimationChannel& channel : animation.channels) e.animated.insert(channel.node);
    return e;
}

nlohmann::json importCounts(const QString& file) {
    QProcess blender;
    blender.start(GLINT_BLENDER, {"--background", "--factory-startup", "--python", GLINT_IMPORT_COUNTS_SCRIPT, "--", file});
    if (!blender.waitForFinished(180000)) return {};
    const QString out = QString::fromUtf8(blender.readAllStandardOutput());
    for (const QString& line : out.split('\n'))
        if (line.startsWith("GLINT_COUNTS ")) return nlohmann::json::parse(line.mid(13).toStdString());
    qWarning("%s", qPrintable(out + QString::fromUtf8(blender.readAllStandardError())));
    return {};
}

} // namespace

class TestBlenderImport : public QObject {
    Q_OBJECT
private slots:
    void blenderImportsWhatGlintWrites() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        Scene scene = test::featureScene();
        // Area lights, which reach Blender as emitting meshes (GLINT_area_light for Glint itself).
        for (const AreaShape shape : {AreaShape::Rectangle, AreaShape::Sphere}) {
            Node node;
            node.name = shape == AreaShape::Rectangle ? "softbox" : "bulb";
            node.component = Light{.type = LightType::Area, .intensity = 50.0f, .radius = 0.1f, .areaShape = shape};
            node.local.translation = {0.0f, 3.0f, 0.0f};
            scene.addNode(node);
        }
        const QString file = dir.filePath("features.gltf");
        saveScene(scene, file.toStdString());
        const nlohmann::json counts = importCounts(file);
        QVERIFY2(!counts.is_null(), "Blender printed no counts");
        qInfo("Blender imported: %s", counts.dump().c_str());
        const Expected e = expectedOf(scene);
        QCOMPARE(counts.at("lights").get<int>(), e.lights);
        QCOMPARE(counts.at("cameras").get<int>(), e.cameras);
        QCOMPARE(counts.at("materials").get<int>(), int(e.materials.size()) + e.areaLights);
        QVERIFY(counts.at("meshes").get<int>() >= e.shapes + e.meshInstances + e.areaLights);
        QVERIFY(counts.at("objects").get<int>() >= e.objects);
        QCOMPARE(counts.at("emissive_objects").get<int>(), e.emissive);
        QCOMPARE(counts.at("animated_objects").get<int>(), int(e.animated.size()));
    }
};

QTEST_APPLESS_MAIN(TestBlenderImport)
#include "test_blender_import.moc"
