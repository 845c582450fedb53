// Portal pairs in glTF: GLINT_shape's `portal` is the glTF index of the partner node, written only
// on the two quads of a pair. Saved and loaded back the pair is the same, a second save is
// byte-identical, a scene without portals writes no `portal` key, and a one-sided link (its
// partner deleted or no longer a quad) is not saved.
#include "io_write_helpers.h"
#ifdef GLINT_VALIDATE_OUTPUT
#include "validator_run.h"
#endif

#include "scene/core/portal.h"
#include "scene/io/scene_io.h"

#include <glm/gtc/quaternion.hpp>

#include <QTemporaryDir>
#include <QtTest>

#include <numbers>

using namespace glint;
namespace fs = std::filesystem;

namespace {

NodeId addQuad(Scene& scene, const std::string& name, glm::vec3 at, float turn, MaterialId material)
{
    Node node;
    node.name = name;
    node.local.translation = at;
    // Upright: the quad's normal (+Y) turned to face along Z, then about Y.
    node.local.rotation = glm::angleAxis(turn, glm::vec3(0, 1, 0)) * glm::angleAxis(0.5f * std::numbers::pi_v<float>, glm::vec3(1, 0, 0));
    Shape quad;
    quad.kind = ShapeKind::Quad;
    quad.size = {2.0f, 1.0f, 2.0f};
    quad.material = material;
    node.component = quad;
    return scene.addNode(std::move(node));
}

void link(Scene& scene, NodeId from, NodeId to)
{
    Shape shape = *scene.at(from).get<Shape>();
    shape.portal = to;
    scene.setComponent(from, shape);
}

// A ball first, so that the pair's indices are 1 and 2, not 0 (the default of a missing number).
Scene portalScene()
{
    Scene scene;
    Material frame;
    frame.name = "frame";
    const MaterialId material = scene.materials.add(frame);
    Node ball;
    ball.name = "ball";
    ball.component = Shape{};
    scene.addNode(std::move(ball));
    const NodeId a = addQuad(scene, "Portal A", {-3, 1, 0}, 0.0f, material);
    const NodeId b = addQuad(scene, "Portal B", {3, 1, 0}, std::numbers::pi_v<float>, material);
    link(scene, a, b);
    link(scene, b, a);
    return scene;
}

nlohmann::json savedJson(const Scene& scene, const fs::path& file)
{
    saveScene(scene, file);
    return nlohmann::json::parse(test::readText(file));
}

const nlohmann::json& shapeOf(const nlohmann::json& root, std::size_t node) { return root["nodes"][node]["extensions"]["GLINT_shape"]; }

} // namespace

class TestPortalIo : public QObject {
    Q_OBJECT

private slots:
    void pairWritesEachOthersIndex()
    {
        QTemporaryDir dir;
        const nlohmann::json root = savedJson(portalScene(), fs::path(dir.path().toStdString()) / "portals.gltf");
        QVERIFY(!shapeOf(root, 0).contains("portal"));
        QCOMPARE(shapeOf(root, 1)["portal"].get<int>(), 2);
        QCOMPARE(shapeOf(root, 2)["portal"].get<int>(), 1);
    }

    void roundTripKeepsThePairByteForByte_data()
    {
        QTest::addColumn<QString>("format");
        QTest::newRow("gltf") << QString(".gltf");
        QTest::newRow("glb") << QString(".glb");
    }

    void roundTripKeepsThePairByteForByte()
    {
        QFETCH(QString, format);
        const Scene scene = portalScene();
        QTemporaryDir first, second;
        const fs::path saved = fs::path(first.path().toStdString()) / ("portals" + format.toStdString());
        saveScene(scene, saved);
        const LoadResult loaded = loadScene(saved);
        for (const Warning& w : loaded.warnings) QVERIFY2(false, (w.code + ": " + w.message).c_str());
        QVERIFY2(loaded.scene == scene, "the scene differs after loading");
        const NodeId a = *loaded.scene.findByName("Portal A");
        const NodeId b = *loaded.scene.findByName("Portal B");
        QCOMPARE(portalPartner(loaded.scene, a), std::optional<NodeId>(b));
        QCOMPARE(portalPartner(loaded.scene, b), std::optional<NodeId>(a));
        const fs::path again = fs::path(second.path().toStdString()) / ("portals" + format.toStdString());
        saveScene(loaded.scene, again);
        QVERIFY2(test::readBytes(saved) == test::readBytes(again), "the second save differs");
#ifdef GLINT_VALIDATE_OUTPUT
        const std::string errors = test::validatorErrors({saved});
        QVERIFY2(errors.empty(), errors.c_str());
#endif
    }

    // The partner deleted, or turned into a disk: the quad left behind is an ordinary quad and
    // saves as one, so the file never carries half a pair.
    void oneSidedLinkIsNotWritten()
    {
        QTemporaryDir dir;
        Scene deleted = portalScene();
        deleted.removeLeaf(*deleted.findByName("Portal B"));
        nlohmann::json root = savedJson(deleted, fs::path(dir.path().toStdString()) / "deleted.gltf");
        QVERIFY(!shapeOf(root, 1).contains("portal"));

        Scene changed = portalScene();
        const NodeId b = *changed.findByName("Portal B");
        Shape disk = *changed.at(b).get<Shape>();
        disk.kind = ShapeKind::Disk;
        changed.setComponent(b, disk);
        root = savedJson(changed, fs::path(dir.path().toStdString()) / "changed.gltf");
        QVERIFY(!shapeOf(root, 1).contains("portal"));
        QVERIFY(!shapeOf(root, 2).contains("portal"));
        const LoadResult loaded = loadScene(fs::path(dir.path().toStdString()) / "changed.gltf");
        QVERIFY(loaded.warnings.empty());
        QVERIFY(!loaded.scene.at(*loaded.scene.findByName("Portal A")).get<Shape>()->portal.valid());
    }
};

QTEST_APPLESS_MAIN(TestPortalIo)
#include "test_portal_io.moc"
