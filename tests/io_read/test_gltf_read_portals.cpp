// GLINT_shape's `portal` on load: a pair of quads naming each other loads linked, whichever is read
// first; every other link is dropped with one warning (invalid-portal) naming the node and the
// problem, never an error or a crash. Each case is one change to a valid file of four quads, the
// last outside the default scene.
#include "io_read_helpers.h"

#include <QTest>

using namespace glint;
using namespace glint::test;

namespace {

Json quad(const Json& portal = nullptr, const char* kind = "quad")
{
    Json shape{{"kind", kind}, {"size", {2, 1, 2}}};
    if (!portal.is_null()) shape["portal"] = portal;
    return {{"extensions", {{"GLINT_shape", shape}}}};
}

// nodes[0] and nodes[1] with the given links, nodes[2] an unlinked quad, nodes[3] outside the scene.
Json portalDoc(const Json& first, const Json& second, const char* firstKind = "quad")
{
    return {{"asset", {{"version", "2.0"}}}, {"scene", 0}, {"scenes", {{{"nodes", {0, 1, 2}}}}},
            {"nodes", {quad(first, firstKind), quad(second), quad(), quad()}}};
}

NodeId portalOf(const Scene& scene, std::uint32_t id) { return scene.at(NodeId{id}).get<Shape>()->portal; }

// nodes[3], outside the scene, is named as dropped: only portal warnings count here.
bool anyPortalWarning(const Warnings& warnings)
{
    for (const Warning& w : warnings)
        if (w.code == "invalid-portal") return true;
    return false;
}

bool warned(const Warnings& warnings, const std::string& part)
{
    for (const Warning& w : warnings)
        if (w.code == "invalid-portal" && w.message.find(part) != std::string::npos) return true;
    return false;
}

} // namespace

class TestGltfReadPortals : public QObject {
    Q_OBJECT

private slots:
    // nodes[0] names nodes[1] before nodes[1] is read: the index resolves through the id table.
    void pairLoadsLinked()
    {
        const LoadResult r = loadJson(portalDoc(1, 0));
        QVERIFY(!anyPortalWarning(r.warnings));
        QCOMPARE(portalOf(r.scene, 1), NodeId{2});
        QCOMPARE(portalOf(r.scene, 2), NodeId{1});
    }

    void pairKeepsSavedIds()
    {
        Json doc = portalDoc(1, 0);
        doc["nodes"][0]["extensions"]["GLINT_node"] = {{"id", 40}};
        doc["nodes"][1]["extensions"]["GLINT_node"] = {{"id", 7}};
        const LoadResult r = loadJson(doc);
        QVERIFY(!anyPortalWarning(r.warnings));
        QCOMPARE(portalOf(r.scene, 40), NodeId{7});
        QCOMPARE(portalOf(r.scene, 7), NodeId{40});
    }

    // The fuzzer's seed (tests/fuzz/seeds/gltf/portals.gltf) is a valid pair, so fuzzing starts
    // from the linked path.
    void fuzzSeedIsAPair()
    {
        const LoadResult r = loadScene(std::filesystem::path(GLINT_FUZZ_SEEDS_DIR) / "gltf" / "portals.gltf");
        QVERIFY(r.warnings.empty());
        QCOMPARE(portalOf(r.scene, 1), NodeId{2});
        QCOMPARE(portalOf(r.scene, 2), NodeId{1});
    }

    void badLinkIsDroppedAndNamed_data()
    {
        QTest::addColumn<QString>("first");
        QTest::addColumn<QString>("second");
        QTest::addColumn<QString>("firstKind");
        QTest::addColumn<QString>("message");
        const QString where = "nodes[0].extensions.GLINT_shape.portal ";
        QTest::newRow("string") << "\"1\"" << "0" << "quad" << where + "must be a node index (a non-negative integer)";
        QTest::newRow("negative") << "-1" << "0" << "quad" << where + "must be a node index";
        QTest::newRow("fraction") << "1.5" << "0" << "quad" << where + "must be a node index";
        QTest::newRow("object") << "{\"node\": 1}" << "0" << "quad" << where + "must be a node index";
        QTest::newRow("out of range") << "7" << "0" << "quad" << where + "is 7, but the file has 4 nodes";
        QTest::newRow("huge") << "18446744073709551615" << "0" << "quad" << where + "is 18446744073709551615, but the file has 4 nodes";
        QTest::newRow("not loaded") << "3" << "0" << "quad" << where + "names nodes[3], which is not loaded";
        QTest::newRow("itself") << "0" << "null" << "quad" << where + "names the node itself";
        QTest::newRow("on a sphere") << "1" << "0" << "sphere" << where + "is on a shape that is not a quad";
        QTest::newRow("partner a sphere") << "1" << "0" << "sphere" << "nodes[1].extensions.GLINT_shape.portal names nodes[0], which is not a quad";
        QTest::newRow("one-sided") << "1" << "null" << "quad" << where + "names nodes[1], which names no portal back: they are not a pair";
        QTest::newRow("partner elsewhere") << "1" << "2" << "quad" << where + "names nodes[1], which names nodes[2]: they are not a pair";
    }

    // The bad link is dropped, and nodes[0] is an ordinary quad (or sphere); loading goes on.
    void badLinkIsDroppedAndNamed()
    {
        QFETCH(QString, first);
        QFETCH(QString, second);
        QFETCH(QString, firstKind);
        QFETCH(QString, message);
        const LoadResult r = loadJson(portalDoc(Json::parse(first.toStdString()), Json::parse(second.toStdString()), qPrintable(firstKind)));
        QVERIFY2(warned(r.warnings, message.toStdString()), qPrintable(message));
        QVERIFY(!portalOf(r.scene, 1).valid());
        QVERIFY(!portalOf(r.scene, 2).valid() || portalOf(r.scene, 2) != NodeId{1});
        QCOMPARE(r.scene.nodes().size(), std::size_t(3));
    }
};

QTEST_APPLESS_MAIN(TestGltfReadPortals)
#include "test_gltf_read_portals.moc"
