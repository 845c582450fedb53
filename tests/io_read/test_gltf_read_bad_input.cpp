// Bad bytes and bad structure: each gives one specific FileError, never a crash, hang or unbounded
// allocation. Every case is one change to a valid generated file, so nothing else can be the cause.
#include "io_read_helpers.h"

#include <QTest>

using namespace glint;
using namespace glint::test;

class TestGltfReadBadInput : public QObject {
    Q_OBJECT

private slots:
    void validTriangleLoads()
    {
        const LoadResult r = loadJson(triangle().finish());
        QCOMPARE(r.scene.nodeCount(), std::size_t(1));
        QCOMPARE(r.scene.meshes.begin()->second.triangleCount(), std::size_t(1));
    }

    void emptyFile() { GLINT_EXPECT_ERROR(loadGltfFromMemory({}, ".", "empty.gltf"), "empty-file", "empty"); }

    void invalidJson() { GLINT_EXPECT_ERROR(loadGltfFromMemory(bytesOf("{\"asset\": {\"version\": \"2.0\"},"), ".", "bad.gltf"), "invalid-json", "not valid JSON"); }

    void binaryGarbage()
    {
        const std::vector<std::uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
        GLINT_EXPECT_ERROR(loadGltfFromMemory(png, ".", "picture.glb"), "not-gltf", "byte 0 (0x89)");
        const std::vector<std::uint8_t> padded = {' ', '\n', 0x00, '{'};
        GLINT_EXPECT_ERROR(loadGltfFromMemory(padded, ".", "zeros.gltf"), "not-gltf", "byte 2 (0x00)");
        // A byte order mark, then JSON: still JSON (its own errors, not this one).
        const std::vector<std::uint8_t> bom = {0xEF, 0xBB, 0xBF, '[', '1', ']'};
        GLINT_EXPECT_ERROR(loadGltfFromMemory(bom, ".", "bom.gltf"), "wrong-type", "top level");
    }
    void topLevelNotAnObject() { GLINT_EXPECT_ERROR(loadGltfFromMemory(bytesOf("[1, 2]"), ".", "bad.gltf"), "wrong-type", "top level"); }

    void deepNestingIsRefusedBeforeParsing()
    {
        const std::string deep = "{\"asset\": {\"version\": \"2.0\"}, \"extras\": " + std::string(100000, '[') + std::string(100000, ']') + "}";
        GLINT_EXPECT_ERROR(loadGltfFromMemory(bytesOf(deep), ".", "deep.gltf"), "json-too-deep", "deeper than 64");
    }

    void bracketsInsideStringsDoNotCount()
    {
        Json doc = triangle().finish();
        doc["extras"] = std::string(1000, '[');
        QCOMPARE(loadJson(doc).scene.unknown["extras"].get<std::string>().size(), std::size_t(1000));
    }

    void wrongTypes_data()
    {
        QTest::addColumn<QString>("pointer");
        QTest::addColumn<QString>("value");
        QTest::addColumn<QString>("where");
        QTest::newRow("nodes is an object") << "/nodes" << "{}" << "nodes must be an array";
        QTest::newRow("mesh index is a string") << "/nodes/0/mesh" << "\"0\"" << "nodes[0].mesh must be an index";
        QTest::newRow("negative index") << "/meshes/0/primitives/0/indices" << "-1" << "indices must be an index";
        QTest::newRow("translation of two") << "/nodes/0/translation" << "[1, 2]" << "nodes[0].translation must be an array of 3 numbers";
        QTest::newRow("name is a number") << "/nodes/0/name" << "7" << "nodes[0].name must be a string";
        QTest::newRow("children not an array") << "/nodes/0/children" << "5" << "children must be an array";
        QTest::newRow("byteLength is a string") << "/bufferViews/0/byteLength" << "\"36\"" << "bufferViews[0].byteLength must be a non-negative integer";
    }

    void wrongTypes()
    {
        QFETCH(QString, pointer);
        QFETCH(QString, value);
        QFETCH(QString, where);
        Json doc = triangle().finish();
        doc[Json::json_pointer(pointer.toStdString())] = Json::parse(value.toStdString());
        GLINT_EXPECT_ERROR(loadJson(doc), "wrong-type", where.toStdString());
    }

    void danglingIndices_data()
    {
        QTest::addColumn<QString>("pointer");
        QTest::addColumn<QString>("message");
        QTest::newRow("mesh") << "/nodes/0/mesh" << "nodes[0].mesh is 5, but the file has 1 meshes";
        QTest::newRow("material") << "/meshes/0/primitives/0/material" << "material is 5, but the file has 0 materials";
        QTest::newRow("camera") << "/nodes/0/camera" << "nodes[0].camera is 5, but the file has 0 cameras";
        QTest::newRow("accessor") << "/meshes/0/primitives/0/indices" << "indices is 5, but the file has 2 accessors";
        QTest::newRow("child") << "/nodes/0/children" << "children[0] is 5, but the file has 1 nodes";
        QTest::newRow("scene") << "/scene" << "scene is 5, but the file has 1 scenes";
        QTest::newRow("texture") << "/materials/0/pbrMetallicRoughness/baseColorTexture/index" << "baseColorTexture.index is 5, but the file has 0 textures";
    }

    void danglingIndices()
    {
        QFETCH(QString, pointer);
        QFETCH(QString, message);
        Json doc = triangle().finish();
        const bool isArray = pointer.endsWith("children");
        doc[Json::json_pointer(pointer.toStdString())] = isArray ? Json::array({5}) : Json(5);
        GLINT_EXPECT_ERROR(loadJson(doc), "dangling-index", message.toStdString());
    }

    void unsupportedRequiredExtension()
    {
        Json doc = triangle().finish();
        doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
        doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
        GLINT_EXPECT_ERROR(loadJson(doc), "unsupported-required-extension", "KHR_draco_mesh_compression");
    }

    void honouredRequiredExtensionLoads()
    {
        Json doc = triangle().finish();
        doc["extensionsRequired"] = {"KHR_texture_transform"};
        QCOMPARE(loadJson(doc).scene.nodeCount(), std::size_t(1));
    }

    void accessorPastItsBufferView()
    {
        Json doc = triangle().finish();
        doc["accessors"][0]["count"] = 103; // 100 more vec3 floats than the 36-byte view holds
        GLINT_EXPECT_ERROR(loadJson(doc), "accessor-out-of-range", "accessor 0 reads 1200 bytes past the end of bufferView 0");
    }

    void bufferViewPastItsBuffer()
    {
        Json doc = triangle().finish();
        doc["bufferViews"][1]["byteLength"] = 600;
        GLINT_EXPECT_ERROR(loadJson(doc), "buffer-view-out-of-range", "past the end of buffer 0 (44 bytes)");
    }

    void hugeCountIsRefusedWithoutAllocating()
    {
        Json doc = triangle().finish();
        doc["accessors"][0].erase("bufferView"); // an all-zero accessor would be allocated in full
        doc["accessors"][0]["count"] = std::uint64_t(1) << 40;
        GLINT_EXPECT_ERROR(loadJson(doc), "huge-count", "accessors[0].count is 1099511627776");
        doc["accessors"][0]["count"] = 100000000; // 1.2 GB of vec3 floats: under the byte cap, yet only zeros
        GLINT_EXPECT_ERROR(loadJson(doc), "huge-count", "accessors[0].count is 100000000 with no bufferView");
    }

    void hugeDeclaredBuffer()
    {
        Json doc = triangle().finish();
        doc["buffers"][0]["byteLength"] = std::uint64_t(1) << 50;
        GLINT_EXPECT_ERROR(loadJson(doc), "buffer-too-large", "buffers[0] declares 1125899906842624 bytes");
    }

    void bufferShorterThanDeclared()
    {
        Json doc = triangle().finish();
        doc["buffers"][0]["byteLength"] = 400;
        GLINT_EXPECT_ERROR(loadJson(doc), "buffer-too-short", "declares 400 bytes, but its data holds only 44");
    }

    void indexOutOfRange()
    {
        GltfBuilder b = triangle();
        b.doc["accessors"][1]["bufferView"] = b.view(std::vector<std::uint16_t>{0, 1, 7});
        GLINT_EXPECT_ERROR(loadJson(b.finish()), "index-out-of-range", "index 2 of primitive 0 of mesh 0 is 7, but there are 3 vertices");
    }

    void sparseIndexOutOfRange()
    {
        GltfBuilder b = triangle();
        const int indices = b.view(std::vector<std::uint16_t>{9});
        const int values = b.view(std::vector<float>{1, 1, 1});
        b.doc["accessors"][0]["sparse"] = {{"count", 1}, {"indices", {{"bufferView", indices}, {"componentType", 5123}}}, {"values", {{"bufferView", values}}}};
        GLINT_EXPECT_ERROR(loadJson(b.finish()), "index-out-of-range", "sparse index 9");
    }

    void malformedDataUri_data()
    {
        QTest::addColumn<QString>("uri");
        QTest::newRow("no base64 marker") << "data:application/octet-stream,AAAA";
        QTest::newRow("bad characters") << "data:application/octet-stream;base64,AA*A";
        QTest::newRow("no comma") << "data:application/octet-stream;base64";
        QTest::newRow("one stray digit") << "data:application/octet-stream;base64,A";
    }

    void malformedDataUri()
    {
        QFETCH(QString, uri);
        Json doc = triangle().finish();
        doc["buffers"][0]["uri"] = uri.toStdString();
        GLINT_EXPECT_ERROR(loadJson(doc), "malformed-data-uri", "buffers[0].uri is a data: URI");
    }

    void nonFinitePosition_data()
    {
        QTest::addColumn<float>("value");
        QTest::newRow("NaN") << std::numeric_limits<float>::quiet_NaN();
        QTest::newRow("Inf") << std::numeric_limits<float>::infinity();
    }

    void nonFinitePosition()
    {
        QFETCH(float, value);
        GltfBuilder b = triangle();
        b.doc["accessors"][0]["bufferView"] = b.view(std::vector<float>{0, 0, 0, value, 0, 0, 0, 1, 0});
        GLINT_EXPECT_ERROR(loadJson(b.finish()), "non-finite-position", "vertex 1 is not a finite number");
    }

    void transformOutOfFloatRange()
    {
        Json doc = triangle().finish();
        doc["nodes"][0]["translation"] = {0, 1e39, 0};
        GLINT_EXPECT_ERROR(loadJson(doc), "non-finite-value", "nodes[0].translation is 1e+39, outside the range of a float");
        doc["nodes"][0].erase("translation");
        doc["nodes"][0]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1e39, 0, 0, 1};
        GLINT_EXPECT_ERROR(loadJson(doc), "non-finite-value", "nodes[0].matrix");
    }

    void nodeGraphs_data()
    {
        QTest::addColumn<QString>("nodes");
        QTest::addColumn<QString>("message");
        QTest::newRow("own child") << R"([{"children": [0]}])" << "node 0 lists itself as a child";
        QTest::newRow("two parents") << R"([{"children": [2]}, {"children": [2]}, {}])" << "node 2 is a child of both node 0 and node 1";
        QTest::newRow("loop") << R"([{"children": [1]}, {"children": [2]}, {"children": [0]}])" << "is its own ancestor";
    }

    void nodeGraphs()
    {
        QFETCH(QString, nodes);
        QFETCH(QString, message);
        Json doc = triangle().finish();
        doc["nodes"] = Json::parse(nodes.toStdString());
        doc["scenes"] = Json::array({Json::object()});
        GLINT_EXPECT_ERROR(loadJson(doc), "node-graph-cycle", message.toStdString());
    }

    // A hierarchy 50,000 nodes deep: no recursion to exhaust the stack, no quadratic loop check.
    void deepNodeChainLoads()
    {
        Json doc = triangle().finish();
        const int depth = 50000;
        doc["nodes"] = Json::array();
        for (int i = 0; i < depth; ++i) doc["nodes"].push_back(i + 1 < depth ? Json{{"children", {i + 1}}} : Json{{"mesh", 0}});
        const LoadResult r = loadJson(doc);
        QCOMPARE(r.scene.nodeCount(), std::size_t(depth));
        QCOMPARE(r.scene.at(NodeId{depth}).parent, NodeId{depth - 1});
    }

    void sceneRootThatIsAChild()
    {
        Json doc = triangle().finish();
        doc["nodes"] = Json::parse(R"([{"children": [1]}, {}])");
        doc["scenes"][0]["nodes"] = {0, 1};
        GLINT_EXPECT_ERROR(loadJson(doc), "node-graph-cycle", "lists node 1 as a root");
    }

    void noSceneLoadsRootsWithWarning()
    {
        Json doc = triangle().finish();
        doc.erase("scenes");
        doc.erase("scene");
        const LoadResult r = loadJson(doc);
        QCOMPARE(r.scene.nodeCount(), std::size_t(1));
        QVERIFY(hasWarning(r.warnings, "no-scene"));
    }

    void nothingAtAllIsAnEmptySceneWithWarning()
    {
        const LoadResult r = loadJson(Json{{"asset", {{"version", "2.0"}}}});
        QCOMPARE(r.scene.nodeCount(), std::size_t(0));
        QCOMPARE(QString::fromStdString(findWarning(r.warnings, "no-scene")->message), QStringLiteral("the file has no scene and no nodes: the scene is empty"));
    }

    void unknownComponentType()
    {
        Json doc = triangle().finish();
        doc["accessors"][0]["componentType"] = 5000;
        GLINT_EXPECT_ERROR(loadJson(doc), "invalid-gltf", "accessors[0] has an unknown componentType or type");
    }

    // A number beyond double range is grammatically valid JSON: it is a non-finite value, named by
    // its JSON path, and no message leaks the parser's exception ids.
    void numberBeyondDoubleRangeIsNonFinite()
    {
        Json doc = triangle().finish();
        doc["nodes"][0]["translation"] = {0, 0, 0};
        std::string text = doc.dump();
        const std::string plain = "\"translation\":[0,0,0]";
        QVERIFY(text.find(plain) != std::string::npos);
        text.replace(text.find(plain), plain.size(), "\"translation\":[0,1e400,0]");
        const Caught caught = errorOf([&] { (void)loadGltfFromMemory(bytesOf(text), ".", "inf.gltf"); });
        QCOMPARE(QString::fromStdString(caught.code), QStringLiteral("non-finite-value"));
        QCOMPARE(QString::fromStdString(caught.file), QStringLiteral("inf.gltf"));
        QCOMPARE(QString::fromStdString(caught.message), QStringLiteral("nodes[0].translation[1] is 1e400, beyond the range of a number"));
        const Caught invalid = errorOf([&] { (void)loadGltfFromMemory(bytesOf("{\"asset\": 1,"), ".", "bad.gltf"); });
        QCOMPARE(QString::fromStdString(invalid.code), QStringLiteral("invalid-json"));
        QVERIFY2(invalid.message.find("json.exception") == std::string::npos, invalid.message.c_str());
    }

    // glTF forbids these camera values; each is repaired and named (file, camera, key, value).
    void degenerateCamerasAreRepairedLoudly_data()
    {
        QTest::addColumn<QString>("camera");
        QTest::addColumn<QString>("message");
        QTest::addColumn<float>("yfov");
        QTest::addColumn<float>("znear");
        QTest::addColumn<float>("zfar");
        QTest::addColumn<float>("xmag");
        const float yfov = Camera{}.yfov;
        QTest::newRow("yfov 0") << R"({"type": "perspective", "perspective": {"yfov": 0, "znear": 0.1}})"
                                << "cameras[0].perspective.yfov is 0 (must be between 0 and pi radians): replaced by 0.6911112" << yfov << 0.1f << 0.0f << 1.0f;
        QTest::newRow("yfov negative") << R"({"type": "perspective", "perspective": {"yfov": -1, "znear": 0.1}})"
                                       << "cameras[0].perspective.yfov is -1" << yfov << 0.1f << 0.0f << 1.0f;
        QTest::newRow("yfov 10 rad") << R"({"type": "perspective", "perspective": {"yfov": 10, "znear": 0.1}})"
                                     << "cameras[0].perspective.yfov is 10" << yfov << 0.1f << 0.0f << 1.0f;
        QTest::newRow("znear 0") << R"({"type": "perspective", "perspective": {"yfov": 1, "znear": 0}})"
                                 << "cameras[0].perspective.znear is 0 (must be greater than 0): replaced by 0.01" << 1.0f << 0.01f << 0.0f << 1.0f;
        QTest::newRow("zfar < znear") << R"({"type": "perspective", "perspective": {"yfov": 1, "znear": 1, "zfar": 0.5}})"
                                      << "cameras[0].perspective.zfar is 0.5 (must be greater than znear): the far plane is dropped" << 1.0f << 1.0f << 0.0f << 1.0f;
        QTest::newRow("xmag 0") << R"({"type": "orthographic", "orthographic": {"xmag": 0, "ymag": 2, "znear": 0, "zfar": 10}})"
                                << "cameras[0].orthographic.xmag is 0 (must not be 0): replaced by 1" << yfov << 0.0f << 10.0f << 1.0f;
    }

    void degenerateCamerasAreRepairedLoudly()
    {
        QFETCH(QString, camera);
        QFETCH(QString, message);
        Json doc = triangle().finish();
        doc["cameras"] = Json::array({Json::parse(camera.toStdString())});
        doc["nodes"].push_back({{"camera", 0}, {"name", "cam"}});
        doc["scenes"][0]["nodes"].push_back(1);
        const LoadResult r = loadJson(doc);
        const Warning* w = findWarning(r.warnings, "invalid-value");
        QVERIFY(w);
        QCOMPARE(QString::fromStdString(w->file), QStringLiteral("test.gltf"));
        QVERIFY2(w->message.find(message.toStdString()) != std::string::npos, w->message.c_str());
        const NodeId id = *r.scene.findByName("cam");
        const Camera* c = r.scene.at(id).get<Camera>();
        QVERIFY(c);
        QTEST(c->yfov, "yfov");
        QTEST(c->znear, "znear");
        QTEST(c->zfar, "zfar");
        QTEST(c->xmag, "xmag");
    }

    void validCameraHasNoWarning()
    {
        Json doc = triangle().finish();
        doc["cameras"] = Json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}, {"zfar", 100}}}}});
        doc["nodes"][0]["camera"] = 0;
        QVERIFY(!hasWarning(loadJson(doc).warnings, "invalid-value"));
    }

    void zeroQuaternionIsIdentityWithWarning()
    {
        Json doc = triangle().finish();
        doc["nodes"][0]["rotation"] = {0, 0, 0, 0};
        const LoadResult r = loadJson(doc);
        const Warning* w = findWarning(r.warnings, "invalid-value");
        QVERIFY(w);
        QCOMPARE(QString::fromStdString(w->file), QStringLiteral("test.gltf"));
        QVERIFY2(w->message.find("nodes[0].rotation is [0, 0, 0, 0], not a rotation") != std::string::npos, w->message.c_str());
        const glm::quat q = r.scene.at(r.scene.roots()[0]).local.rotation;
        QCOMPARE(q, glm::quat(1.0f, 0.0f, 0.0f, 0.0f));
        // A far-from-unit rotation is normalised (named); exporters' rounding passes quietly.
        doc["nodes"][0]["rotation"] = {0, 0, 0, 2};
        QVERIFY(hasWarning(loadJson(doc).warnings, "invalid-value"));
        doc["nodes"][0]["rotation"] = {0, 0, 0, 1.0001};
        QVERIFY(!hasWarning(loadJson(doc).warnings, "invalid-value"));
    }

    void materialFactorsOutOfRangeAreClamped()
    {
        Json doc = triangle().finish();
        doc["materials"] = Json::array({{{"pbrMetallicRoughness", {{"roughnessFactor", -5}, {"metallicFactor", 7}}}}});
        doc["meshes"][0]["primitives"][0]["material"] = 0;
        const LoadResult r = loadJson(doc);
        const Material& m = r.scene.materials.begin()->second;
        QCOMPARE(m.roughnessFactor, 0.0f);
        QCOMPARE(m.metallicFactor, 1.0f);
        std::vector<std::string> messages;
        for (const Warning& w : r.warnings)
            if (w.code == "invalid-value" && w.file == "test.gltf") messages.push_back(w.message);
        QCOMPARE(messages.size(), std::size_t(2));
        QCOMPARE(QString::fromStdString(messages[0]), QStringLiteral("materials[0].pbrMetallicRoughness.metallicFactor is 7, outside 0..1: clamped to 1"));
        QCOMPARE(QString::fromStdString(messages[1]), QStringLiteral("materials[0].pbrMetallicRoughness.roughnessFactor is -5, outside 0..1: clamped to 0"));
    }

    // GLINT_materials_volume_scatter: a scattered share above 1 would add light and |g| = 1 is a
    // delta lobe, so both are clamped like glTF's own factors, each one named.
    void volumeScatterOutOfRangeIsClamped()
    {
        Json doc = triangle().finish();
        doc["materials"] = Json::parse(R"([{"extensions": {"GLINT_materials_volume_scatter": {"scatterColor": [1.5, -0.5, 0.5], "scatterAnisotropy": 1}}}])");
        doc["meshes"][0]["primitives"][0]["material"] = 0;
        const LoadResult r = loadJson(doc);
        const Material& m = r.scene.materials.begin()->second;
        QCOMPARE(m.scatterColor, glm::vec3(1.0f, 0.0f, 0.5f));
        QCOMPARE(m.scatterAnisotropy, 0.99f);
        std::vector<std::string> messages;
        for (const Warning& w : r.warnings)
            if (w.code == "invalid-value" && w.file == "test.gltf") messages.push_back(w.message);
        QCOMPARE(messages.size(), std::size_t(3));
        const QString at = QStringLiteral("materials[0].extensions.GLINT_materials_volume_scatter.");
        QCOMPARE(QString::fromStdString(messages[0]), at + QStringLiteral("scatterColor[0] is 1.5, outside 0..1: clamped to 1"));
        QCOMPARE(QString::fromStdString(messages[1]), at + QStringLiteral("scatterColor[1] is -0.5, outside 0..1: clamped to 0"));
        QCOMPARE(QString::fromStdString(messages[2]), at + QStringLiteral("scatterAnisotropy is 1, outside -0.99..0.99: clamped to 0.99"));

        doc["materials"][0]["extensions"]["GLINT_materials_volume_scatter"] = {{"scatterAnisotropy", -2}};
        QCOMPARE(loadJson(doc).scene.materials.begin()->second.scatterAnisotropy, -0.99f);
        doc["materials"][0]["extensions"]["GLINT_materials_volume_scatter"] = {{"scatterColor", {1, 1}}};
        GLINT_EXPECT_ERROR(loadJson(doc), "wrong-type", "scatterColor");
    }

    void indicesMustBeUnsignedIntegers()
    {
        Json doc = triangle().finish();
        doc["meshes"][0]["primitives"][0]["indices"] = 0; // the float positions as indices
        GLINT_EXPECT_ERROR(loadJson(doc), "wrong-type", "must be unsigned integer scalars");
    }
};

QTEST_APPLESS_MAIN(TestGltfReadBadInput)
#include "test_gltf_read_bad_input.moc"
