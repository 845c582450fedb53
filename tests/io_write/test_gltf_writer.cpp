// The glTF writer: determinism (twice, under a German locale), and the structure of a scene that
// uses every feature, checked on the written JSON.
#include "feature_scene.h"
#include "io_write_helpers.h"

#include "scene/io/gltf_write/gltf_writer.h"
#include "scene/io/scene_io.h"

#include <QTemporaryDir>
#include <QtTest>

#include <clocale>

using namespace glint;
using nlohmann::json;

namespace {

std::filesystem::path dirPath(const QTemporaryDir& dir) { return dir.path().toStdString(); }

bool hasWarning(const Warnings& warnings, const std::string& code)
{
    return std::any_of(warnings.begin(), warnings.end(), [&](const Warning& w) { return w.code == code; });
}

// Restores the C locale however the test ends.
struct LocaleGuard {
    ~LocaleGuard() { std::setlocale(LC_ALL, "C"); }
};

} // namespace

class TestGltfWriter : public QObject {
    Q_OBJECT

private:
    json writtenJson() { return test::glbJson(writeGlb(test::featureScene())); }

private slots:
    void glbIsIdenticalTwice()
    {
        const auto first = writeGlb(test::featureScene());
        const auto second = writeGlb(test::featureScene());
        QVERIFY(first.size() > 1000);
        QVERIFY(first == second);
    }

    void gltfSetIsIdenticalTwiceAndUnderGermanLocale()
    {
        QTemporaryDir a, b, c;
        saveScene(test::featureScene(), dirPath(a) / "scene.gltf");
        saveScene(test::featureScene(), dirPath(b) / "scene.gltf");
        {
            LocaleGuard guard;
            QVERIFY2(std::setlocale(LC_ALL, "de_DE.UTF-8") != nullptr,
                     "the locale de_DE.UTF-8 is missing: generate it (localedef -i de_DE -f UTF-8 de_DE.UTF-8)");
            saveScene(test::featureScene(), dirPath(c) / "scene.gltf");
        }
        const auto files = test::listFiles(dirPath(a));
        QCOMPARE(files.size(), std::size_t{4}); // .gltf, .bin, project file, the external image
        QVERIFY(files == test::listFiles(dirPath(b)));
        QVERIFY(files == test::listFiles(dirPath(c)));
        for (const std::string& f : files) {
            QVERIFY2(test::readBytes(dirPath(a) / f) == test::readBytes(dirPath(b) / f), f.c_str());
            QVERIFY2(test::readBytes(dirPath(a) / f) == test::readBytes(dirPath(c) / f), f.c_str());
        }
        QVERIFY(test::readText(dirPath(c) / "scene.glint.json").find("0,7") == std::string::npos);
    }

    void floatsAreShortestDecimals()
    {
        QTemporaryDir dir;
        saveScene(test::featureScene(), dirPath(dir) / "scene.gltf");
        const std::string text = test::readText(dirPath(dir) / "scene.gltf");
        QVERIFY(text.find("\"roughnessFactor\": 0.6") != std::string::npos);
        QVERIFY(text.find("\"ior\": 1.33") != std::string::npos);
        QVERIFY(text.find("0.60000002384185791") == std::string::npos);
        QVERIFY(text.find("\"alphaCutoff\": 0.3") != std::string::npos);
    }

    void assetAndExtensionsUsed()
    {
        const json j = writtenJson();
        QCOMPARE(j["asset"]["version"].get<std::string>(), std::string("2.0"));
        QCOMPARE(j["asset"]["generator"].get<std::string>(), std::string("Glint ") + GLINT_EXPECTED_VERSION);
        QCOMPARE(j["asset"]["copyright"].get<std::string>(), std::string("generated for Glint's tests"));
        QCOMPARE(j["extras"]["sceneNote"].get<double>(), 0.1);
        const std::vector<std::string> used = j["extensionsUsed"];
        const std::vector<std::string> expected{"EXT_glint_test_node", "EXT_glint_test_unknown", "GLINT_baked_camera_path",
                                                "GLINT_camera", "GLINT_camera_path", "GLINT_light", "GLINT_materials_volume_scatter", "GLINT_node",
                                                "GLINT_shape", "GLINT_shape_fallback", "KHR_lights_punctual",
                                                "KHR_materials_emissive_strength", "KHR_materials_ior",
                                                "KHR_materials_specular", "KHR_materials_transmission",
                                                "KHR_materials_volume", "KHR_texture_transform"};
        QVERIFY(used == expected);
        QVERIFY(!j.contains("extensionsRequired"));
    }

    void nodesKeepIdsHierarchyAndComponents()
    {
        const Scene scene = test::featureScene();
        const json j = writtenJson();
        QCOMPARE(j["nodes"].size(), scene.nodeCount());
        std::size_t index = 0;
        for (const auto& [id, node] : scene.nodes()) {
            QCOMPARE(j["nodes"][index]["extensions"]["GLINT_node"]["id"].get<std::uint32_t>(), id.value);
            ++index;
        }
        QCOMPARE(j["scene"].get<int>(), 0);
        QCOMPARE(j["scenes"][0]["nodes"].size(), scene.roots().size());
        const json& root = j["nodes"][0];
        QCOMPARE(root["name"].get<std::string>(), std::string("root"));
        QVERIFY(root["scale"] == json({2, 2, 2}));
        QCOMPARE(root["children"].size(), scene.at(NodeId{1}).children.size());
        const json& hidden = j["nodes"][scene.findByName("hidden")->value - 1];
        QCOMPARE(hidden["extensions"]["GLINT_node"]["visible"].get<bool>(), false);
        QVERIFY(hidden["extensions"]["EXT_glint_test_node"]["payload"] == json({1, 2, 3}));
        QCOMPARE(hidden["extras"]["tag"].get<std::string>(), std::string("keep me"));
    }

    void shapesHaveFallbackMeshes()
    {
        const Scene scene = test::featureScene();
        const json j = writtenJson();
        const json& ball = j["nodes"][scene.findByName("ball")->value - 1];
        const json& shape = ball["extensions"]["GLINT_shape"];
        QCOMPARE(shape["kind"].get<std::string>(), std::string("sphere"));
        QCOMPARE(shape["radius"].get<double>(), 0.25);
        QCOMPARE(shape["material"].get<int>(), 1);
        const json& fallback = j["meshes"][ball["mesh"].get<int>()];
        QVERIFY(fallback["extensions"].contains("GLINT_shape_fallback"));
        QCOMPARE(fallback["primitives"][0]["material"].get<int>(), 1);
        QCOMPARE(j["meshes"].size(), std::size_t{1 + 3}); // the quad, then one fallback per shape node
        QVERIFY(!j["meshes"][0]["extensions"].contains("GLINT_shape_fallback"));
        const json& floor = j["nodes"][scene.findByName("floor")->value - 1];
        QCOMPARE(floor["extensions"]["GLINT_shape"]["kind"].get<std::string>(), std::string("groundPlane"));
    }

    void lightsAndCameras()
    {
        const Scene scene = test::featureScene();
        const json j = writtenJson();
        const json& lights = j["extensions"]["KHR_lights_punctual"]["lights"];
        QCOMPARE(lights.size(), std::size_t{3});
        QCOMPARE(lights[0]["type"].get<std::string>(), std::string("directional"));
        QCOMPARE(lights[0]["extensions"]["GLINT_light"]["angularDiameter"].get<double>(), 0.00935);
        QCOMPARE(lights[1]["extensions"]["GLINT_light"]["radius"].get<double>(), 0.1);
        QCOMPARE(lights[1]["range"].get<double>(), 20.0);
        QCOMPARE(lights[2]["spot"]["outerConeAngle"].get<double>(), 0.5);
        QVERIFY(!lights[2].contains("extensions")); // a delta spot light
        const json& shot = j["nodes"][scene.findByName("shot")->value - 1];
        const json& camera = j["cameras"][shot["camera"].get<int>()];
        QCOMPARE(camera["type"].get<std::string>(), std::string("perspective"));
        QCOMPARE(camera["perspective"]["yfov"].get<double>(), 0.8);
        QCOMPARE(camera["extensions"]["GLINT_camera"]["focusDistance"].get<double>(), 3.5);
        QCOMPARE(camera["extensions"]["GLINT_camera"]["exposure"].get<double>(), -0.5);
        const json& path = shot["extensions"]["GLINT_camera_path"];
        QCOMPARE(path["rotation"].get<std::string>(), std::string("squad"));
        QCOMPARE(path["keys"].size(), std::size_t{3});
        const CameraKey& key = scene.at(*scene.findByName("shot")).get<Camera>()->path.keys[1];
        QCOMPARE(path["keys"][1]["q"][1].get<double>(), key.orientation.y); // exact double
        QCOMPARE(path["keys"][1]["t"].get<double>(), 0.5);
        const json& top = j["cameras"][j["nodes"][scene.findByName("top")->value - 1]["camera"].get<int>()];
        QCOMPARE(top["orthographic"]["zfar"].get<double>(), 50.0);
    }

    void materialCarriesEveryExtension()
    {
        const json m = writtenJson()["materials"][0];
        const json& base = m["pbrMetallicRoughness"]["baseColorTexture"];
        QCOMPARE(base["index"].get<int>(), 0);
        const json& transform = base["extensions"]["KHR_texture_transform"];
        QVERIFY(transform["offset"] == json({0.5, 0.25}));
        QVERIFY(transform["scale"] == json({2, 3}));
        QCOMPARE(transform["rotation"].get<double>(), 0.1);
        QCOMPARE(transform["texCoord"].get<int>(), 1);
        QCOMPARE(m["normalTexture"]["scale"].get<double>(), 0.5);
        QCOMPARE(m["occlusionTexture"]["strength"].get<double>(), 0.8);
        QCOMPARE(m["occlusionTexture"]["texCoord"].get<int>(), 1);
        const json& ext = m["extensions"];
        QCOMPARE(ext["KHR_materials_emissive_strength"]["emissiveStrength"].get<double>(), 4.0);
        QCOMPARE(ext["KHR_materials_specular"]["specularFactor"].get<double>(), 0.5);
        QVERIFY(ext["KHR_materials_specular"]["specularColorFactor"] == json({0.9, 0.8, 0.7}));
        QCOMPARE(ext["KHR_materials_transmission"]["transmissionFactor"].get<double>(), 0.9);
        QCOMPARE(ext["KHR_materials_ior"]["ior"].get<double>(), 1.33);
        QCOMPARE(ext["KHR_materials_volume"]["thicknessFactor"].get<double>(), 0.1);
        QCOMPARE(ext["KHR_materials_volume"]["attenuationDistance"].get<double>(), 2.0);
        QVERIFY(ext["GLINT_materials_volume_scatter"]["scatterColor"] == json({0.8, 0.7, 0.6}));
        QCOMPARE(ext["GLINT_materials_volume_scatter"]["scatterAnisotropy"].get<double>(), 0.4);
        QVERIFY(ext["EXT_glint_test_unknown"] == json({{"kept", true}, {"value", 1.5}}));
        QCOMPARE(m["extras"]["note"].get<std::string>(), std::string("verbatim"));
        QCOMPARE(m["alphaMode"].get<std::string>(), std::string("MASK"));
        QVERIFY(!m.contains("doubleSided"));
        const json plain = writtenJson()["materials"][1];
        QVERIFY(!plain.contains("extensions")); // defaults write no extension
        QCOMPARE(plain["alphaMode"].get<std::string>(), std::string("BLEND"));
        QCOMPARE(plain["doubleSided"].get<bool>(), true);
    }

    // GLINT_materials_volume_scatter is written only where a value differs from its default, each
    // value alone, and reads back to the same material.
    void volumeScatterIsWrittenWhenSetAndReadsBack()
    {
        Scene scene;
        Material colourOnly;
        colourOnly.scatterColor = {0.5f, 0.25f, 1.0f};
        Material anisotropyOnly;
        anisotropyOnly.scatterAnisotropy = -0.99f;
        scene.materials.add(colourOnly);
        scene.materials.add(anisotropyOnly);
        scene.materials.add(Material{});
        const std::vector<std::uint8_t> glb = writeGlb(scene);
        const json j = test::glbJson(glb);
        const json& first = j["materials"][0]["extensions"]["GLINT_materials_volume_scatter"];
        QVERIFY(first == json({{"scatterColor", {0.5, 0.25, 1}}}));
        const json& second = j["materials"][1]["extensions"]["GLINT_materials_volume_scatter"];
        QVERIFY(second == json({{"scatterAnisotropy", -0.99}}));
        QVERIFY(!j["materials"][2].contains("extensions"));
        const std::vector<std::string> used = j["extensionsUsed"];
        QVERIFY(std::find(used.begin(), used.end(), "GLINT_materials_volume_scatter") != used.end());
        QVERIFY(!j.contains("extensionsRequired"));

        QTemporaryDir dir;
        const std::filesystem::path file = dirPath(dir) / "scatter.glb";
        saveScene(scene, file);
        const LoadResult loaded = loadScene(file);
        // (The scene has no nodes: "no-scene" is expected, nothing about the materials.)
        QVERIFY(!hasWarning(loaded.warnings, "invalid-value"));
        QVERIFY(!hasWarning(loaded.warnings, "extension-dropped"));
        QVERIFY(loaded.scene.materials == scene.materials);
    }

    void buffersAreAlignedAndPositionsBounded()
    {
        const json j = writtenJson();
        for (const json& view : j["bufferViews"]) QCOMPARE(view["byteOffset"].get<std::size_t>() % 4, std::size_t{0});
        const json& attributes = j["meshes"][0]["primitives"][0]["attributes"];
        const json& position = j["accessors"][attributes["POSITION"].get<int>()];
        QVERIFY(position["min"] == json({-0.5, -0.5, 0}));
        QVERIFY(position["max"] == json({0.5, 0.5, 0}));
        for (const char* name : {"NORMAL", "TANGENT", "TEXCOORD_0", "TEXCOORD_1", "COLOR_0"}) QVERIFY2(attributes.contains(name), name);
        const json& indices = j["accessors"][j["meshes"][0]["primitives"][0]["indices"].get<int>()];
        QCOMPARE(indices["componentType"].get<int>(), 5123);
        QVERIFY(!j["buffers"][0].contains("uri")); // GLB: the BIN chunk
    }

    void indicesWidenOnlyWhenNeeded()
    {
        for (const std::uint32_t vertexCount : {65535u, 65536u}) {
            Scene scene;
            Primitive p;
            p.positions.assign(vertexCount, glm::vec3(0.0f));
            p.indices = {0, 1, vertexCount - 1};
            scene.addNode(Node{.name = "n", .component = MeshInstance{scene.meshes.add({.primitives = {p}})}});
            const json j = test::glbJson(writeGlb(scene));
            const int expected = vertexCount - 1 < 65535 ? 5123 : 5125;
            QCOMPARE(j["accessors"][1]["componentType"].get<int>(), expected);
        }
    }

    void animationsAndBakedCameraPath()
    {
        const json j = writtenJson();
        QCOMPARE(j["animations"].size(), std::size_t{2});
        const json& move = j["animations"][0];
        QCOMPARE(move["name"].get<std::string>(), std::string("move"));
        QCOMPARE(move["samplers"][0]["interpolation"].get<std::string>(), std::string("LINEAR"));
        QCOMPARE(move["samplers"][1]["interpolation"].get<std::string>(), std::string("STEP"));
        QCOMPARE(move["samplers"][2]["interpolation"].get<std::string>(), std::string("CUBICSPLINE"));
        QCOMPARE(j["accessors"][move["samplers"][2]["output"].get<int>()]["count"].get<int>(), 6);
        QVERIFY(j["accessors"][move["samplers"][0]["input"].get<int>()]["max"] == json({2}));
        QCOMPARE(move["extras"]["take"].get<int>(), 3);
        const json& baked = j["animations"][1];
        QVERIFY(baked["extensions"].contains("GLINT_baked_camera_path"));
        for (const json& sampler : baked["samplers"]) {
            QCOMPARE(sampler["interpolation"].get<std::string>(), std::string("LINEAR"));
            // 1 s at the project's 30 fps: 31 samples, the last key included.
            QCOMPARE(j["accessors"][sampler["input"].get<int>()]["count"].get<int>(), 31);
        }
    }

    void imagesKeepTheirBytesAndPlaces()
    {
        QTemporaryDir dir;
        saveScene(test::featureScene(), dirPath(dir) / "scene.gltf");
        QVERIFY(test::readBytes(dirPath(dir) / "textures" / "checker.png") == test::checkerPng());
        const json j = json::parse(test::readText(dirPath(dir) / "scene.gltf"));
        QCOMPARE(j["images"][0]["uri"].get<std::string>(), std::string("textures/checker.png"));
        const json& embedded = j["images"][1];
        QCOMPARE(embedded["mimeType"].get<std::string>(), std::string("image/png"));
        const json& view = j["bufferViews"][embedded["bufferView"].get<int>()];
        const std::string binName = j["buffers"][0]["uri"];
        QVERIFY(binName.starts_with("scene.") && binName.ends_with(".bin"));
        const auto bin = test::readBytes(dirPath(dir) / binName);
        QCOMPARE(bin.size(), j["buffers"][0]["byteLength"].get<std::size_t>());
        const auto offset = view["byteOffset"].get<std::ptrdiff_t>();
        QVERIFY(std::vector<std::uint8_t>(bin.begin() + offset, bin.begin() + offset + view["byteLength"].get<std::ptrdiff_t>()) == test::bluePng());

        const json glb = writtenJson(); // a .glb holds every image in its BIN chunk
        QVERIFY(!glb["images"][0].contains("uri"));
        QVERIFY(glb["images"][0].contains("bufferView"));
    }

    void imagesOutsideTheFolderAreEmbedded()
    {
        Scene scene = test::featureScene();
        scene.images.at(ImageId{1}).uri = "../escape.png";
        QTemporaryDir dir;
        const SaveReport report = saveScene(scene, dirPath(dir) / "scene.gltf");
        QVERIFY(hasWarning(report.dropped, "image-embedded"));
        QVERIFY(!std::filesystem::exists(dirPath(dir) / ".." / "escape.png"));
        const json j = json::parse(test::readText(dirPath(dir) / "scene.gltf"));
        QVERIFY(j["images"][0].contains("bufferView"));
    }

    void reportNamesWhatIsDropped()
    {
        Scene scene = test::featureScene();
        Animation weights;
        weights.channels.push_back({.node = NodeId{2}, .path = AnimationPath::Weights, .times = {0.0f}, .values = {1.0f}});
        scene.animations.add(weights);
        SaveReport report;
        writeGlb(scene, &report);
        QVERIFY(hasWarning(report.dropped, "skin-dropped"));         // from Scene::unsupported
        QVERIFY(hasWarning(report.dropped, "weights-animation-dropped"));
        QVERIFY(hasWarning(report.dropped, "empty-animation"));
        QCOMPARE(report.dropped.size(), std::size_t{3});

        QTemporaryDir dir;
        const SaveReport clean = saveScene(test::featureScene(), dirPath(dir) / "scene.gltf");
        QCOMPARE(clean.dropped.size(), std::size_t{1});
        QCOMPARE(clean.written.size(), std::size_t{4});
        QCOMPARE(clean.written[2].filename().string(), std::string("scene.gltf"));
        QCOMPARE(clean.written[3].filename().string(), std::string("scene.glint.json"));
    }

    void resaveReplacesTheOldBuffer()
    {
        QTemporaryDir dir;
        saveScene(test::largeScene(4, 0), dirPath(dir) / "scene.gltf");
        saveScene(test::largeScene(4, 1), dirPath(dir) / "scene.gltf");
        const auto files = test::listFiles(dirPath(dir));
        QCOMPARE(std::count_if(files.begin(), files.end(), [](const std::string& f) { return f.ends_with(".bin"); }), 1);
    }

    void rejectsOtherExtensions()
    {
        QTemporaryDir dir;
        try {
            saveScene(test::featureScene(), dirPath(dir) / "scene.obj");
            QFAIL("saving as .obj must fail");
        } catch (const FileError& e) {
            QCOMPARE(e.code(), std::string("unsupported-format"));
        }
    }
};

QTEST_APPLESS_MAIN(TestGltfWriter)
#include "test_gltf_writer.moc"
