// Nodes, components, materials, animations and what Glint keeps without understanding it.
#include "io_read_helpers.h"

#include <QTest>

#include <algorithm>

#include <glm/gtc/epsilon.hpp>

using namespace glint;
using namespace glint::test;

namespace {

// Three nodes: 0 (mesh) with child 1, and 2; ids as given (0: no GLINT_node).
Json threeNodes(std::uint32_t id0, std::uint32_t id1, std::uint32_t id2)
{
    Json doc = triangle().finish();
    doc["nodes"] = Json::array({{{"name", "a"}, {"mesh", 0}, {"children", {1}}}, {{"name", "b"}}, {{"name", "c"}}});
    doc["scenes"][0]["nodes"] = {0, 2};
    const std::uint32_t ids[] = {id0, id1, id2};
    for (std::size_t i = 0; i < 3; ++i)
        if (ids[i]) doc["nodes"][i]["extensions"]["GLINT_node"] = {{"id", ids[i]}};
    return doc;
}

// Compared as text: QCOMPARE has no overload for nlohmann::json, and the text shows the difference.
QString jsonText(const Json& value) { return QString::fromStdString(value.dump()); }

NodeId idOf(const Scene& scene, const std::string& name) { return *scene.findByName(name); }

Json withLights(Json doc, Json lights)
{
    doc["extensions"]["KHR_lights_punctual"]["lights"] = std::move(lights);
    return doc;
}

} // namespace

class TestGltfReadScene : public QObject {
    Q_OBJECT

private slots:
    void idsFollowNodeOrderWithoutGlintNode()
    {
        const Scene scene = loadJson(threeNodes(0, 0, 0)).scene;
        QCOMPARE(idOf(scene, "a"), NodeId{1});
        QCOMPARE(idOf(scene, "b"), NodeId{2});
        QCOMPARE(idOf(scene, "c"), NodeId{3});
        QCOMPARE(scene.at(NodeId{2}).parent, NodeId{1});
        QCOMPARE(scene.roots(), (std::vector<NodeId>{NodeId{1}, NodeId{3}}));
    }

    void savedIdsAreKept()
    {
        const Scene scene = loadJson(threeNodes(40, 7, 12)).scene;
        QCOMPARE(idOf(scene, "a"), NodeId{40});
        QCOMPARE(idOf(scene, "b"), NodeId{7});
        QCOMPARE(idOf(scene, "c"), NodeId{12});
    }

    void duplicateIdsAreReplacedWithWarning()
    {
        const LoadResult r = loadJson(threeNodes(5, 5, 0));
        QCOMPARE(idOf(r.scene, "a"), NodeId{5});
        QCOMPARE(idOf(r.scene, "b"), NodeId{2});
        QCOMPARE(idOf(r.scene, "c"), NodeId{3});
        QVERIFY(hasWarning(r.warnings, "duplicate-node-id"));
    }

    void hiddenNode()
    {
        Json doc = threeNodes(1, 2, 3);
        doc["nodes"][2]["extensions"]["GLINT_node"]["visible"] = false;
        const Scene scene = loadJson(doc).scene;
        QVERIFY(scene.at(NodeId{1}).visible);
        QVERIFY(!scene.at(NodeId{3}).visible);
    }

    void nodesOutsideTheDefaultSceneAreNamedAsDropped()
    {
        Json doc = threeNodes(0, 0, 0);
        doc["scenes"].push_back({{"nodes", {2}}});
        doc["scenes"][0]["nodes"] = {0};
        const LoadResult r = loadJson(doc);
        QCOMPARE(r.scene.nodeCount(), std::size_t(2));
        QVERIFY(hasWarning(r.warnings, "node-dropped"));
        QVERIFY(hasWarning(r.warnings, "scene-dropped"));
        QCOMPARE(r.scene.unsupported.size(), std::size_t(2));
    }

    void trsTransform()
    {
        Json doc = triangle().finish();
        doc["nodes"][0]["translation"] = {1, 2, 3};
        doc["nodes"][0]["rotation"] = {0, 0.6, 0, 0.8};
        doc["nodes"][0]["scale"] = {2, 2, 2};
        const Transform t = loadJson(doc).scene.at(NodeId{1}).local;
        QCOMPARE(t.translation, glm::vec3(1, 2, 3));
        QCOMPARE(t.rotation, glm::quat(0.8f, 0.0f, 0.6f, 0.0f));
        QCOMPARE(t.scale, glm::vec3(2));
    }

    void matrixIsDecomposed()
    {
        Json doc = triangle().finish();
        doc["nodes"][0]["matrix"] = {0, 0, -2, 0, 0, 2, 0, 0, 2, 0, 0, 0, 5, 6, 7, 1}; // 90 degrees about Y, scale 2
        const LoadResult r = loadJson(doc);
        const Transform t = r.scene.at(NodeId{1}).local;
        QCOMPARE(t.translation, glm::vec3(5, 6, 7));
        QVERIFY(glm::all(glm::epsilonEqual(t.scale, glm::vec3(2), 1e-5f)));
        QVERIFY(std::abs(std::abs(t.rotation.y) - std::sqrt(0.5f)) < 1e-5f);
        QVERIFY(!hasWarning(r.warnings, "matrix-shear"));
    }

    void shearedMatrixWarns()
    {
        Json doc = triangle().finish();
        doc["nodes"][0]["matrix"] = {1, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        QVERIFY(hasWarning(loadJson(doc).warnings, "matrix-shear"));
    }

    void zeroScaleWarns()
    {
        Json doc = triangle().finish();
        doc["nodes"][0]["scale"] = {1, 0, 1};
        const LoadResult r = loadJson(doc);
        QCOMPARE(r.scene.at(NodeId{1}).local.scale, glm::vec3(1, 0, 1));
        QCOMPARE(QString::fromStdString(findWarning(r.warnings, "zero-scale")->message), QStringLiteral("nodes[0] has a zero scale: it and its children are invisible"));
    }

    void meshCameraAndLightSplit()
    {
        Json doc = withLights(triangle().finish(), Json::array({{{"type", "point"}, {"intensity", 50}}}));
        doc["cameras"] = Json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}}});
        doc["nodes"][0]["name"] = "rig";
        doc["nodes"][0]["camera"] = 0;
        doc["nodes"][0]["extensions"]["KHR_lights_punctual"] = {{"light", 0}};
        const LoadResult r = loadJson(doc);
        const Node& rig = r.scene.at(NodeId{1});
        QVERIFY(rig.get<MeshInstance>());
        QCOMPARE(rig.children.size(), std::size_t(2));
        const Node& camera = r.scene.at(rig.children[0]);
        QCOMPARE(QString::fromStdString(camera.name), QStringLiteral("rig.camera"));
        QCOMPARE(camera.get<Camera>()->yfov, 0.5f);
        QCOMPARE(camera.local, Transform{});
        QCOMPARE(QString::fromStdString(r.scene.at(rig.children[1]).name), QStringLiteral("rig.light"));
        QCOMPARE(r.scene.at(rig.children[1]).get<Light>()->intensity, 50.0f);
        QCOMPARE(std::count_if(r.warnings.begin(), r.warnings.end(), [](const Warning& w) { return w.code == "split-node"; }), 2);
    }

    void lightsKeepPhotometricUnits()
    {
        Json lights = Json::parse(R"([
            {"type": "directional", "intensity": 3.5, "color": [1, 0.5, 0.25], "extensions": {"GLINT_light": {"angularDiameter": 0.01}}},
            {"type": "spot", "intensity": 800, "range": 20, "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.4}, "extensions": {"GLINT_light": {"radius": 0.05}}}])");
        Json doc = withLights(threeNodes(0, 0, 0), lights);
        doc["nodes"][1]["extensions"]["KHR_lights_punctual"] = {{"light", 0}};
        doc["nodes"][2]["extensions"]["KHR_lights_punctual"] = {{"light", 1}};
        const Scene scene = loadJson(doc).scene;
        const Light sun = *scene.at(NodeId{2}).get<Light>();
        QCOMPARE(sun.type, LightType::Sun);
        QCOMPARE(sun.intensity, 3.5f);
        QCOMPARE(sun.color, glm::vec3(1, 0.5f, 0.25f));
        QCOMPARE(sun.angularDiameter, 0.01f);
        const Light spot = *scene.at(NodeId{3}).get<Light>();
        QCOMPARE(spot.type, LightType::Spot);
        QCOMPARE(spot.intensity, 800.0f);
        QCOMPARE(spot.range, 20.0f);
        QCOMPARE(spot.innerConeAngle, 0.2f);
        QCOMPARE(spot.outerConeAngle, 0.4f);
        QCOMPARE(spot.radius, 0.05f);
        QVERIFY(scene.unknown.is_null() || !scene.unknown.contains("extensions"));
    }

    void glintCameraAndPath()
    {
        Json doc = triangle().finish();
        doc["cameras"] = Json::parse(R"([{"type": "orthographic", "orthographic": {"xmag": 2, "ymag": 1.5, "znear": 0.5, "zfar": 50},
                                          "extensions": {"GLINT_camera": {"lensRadius": 0.02, "focusDistance": 4, "exposure": -1}}}])");
        doc["nodes"][0] = Json::parse(R"({"camera": 0, "extensions": {"GLINT_camera_path": {"rotation": "slerp", "constantSpeed": true, "keys": [
            {"t": 0, "p": [0, 1, 2], "q": [0, 0, 0, 1], "yfov": 0.5, "focus": 3, "lens": 0.01},
            {"t": 2.5, "p": [0.1, 1, 5], "q": [0, 0.6, 0, 0.8], "yfov": 0.6, "focus": 4, "lens": 0}]}}})");
        const Camera c = *loadJson(doc).scene.at(NodeId{1}).get<Camera>();
        QCOMPARE(c.projection, Projection::Orthographic);
        QCOMPARE(c.xmag, 2.0f);
        QCOMPARE(c.ymag, 1.5f);
        QCOMPARE(c.znear, 0.5f);
        QCOMPARE(c.zfar, 50.0f);
        QCOMPARE(c.lensRadius, 0.02f);
        QCOMPARE(c.focusDistance, 4.0f);
        QCOMPARE(c.exposure, -1.0f);
        QCOMPARE(c.path.rotation, RotationInterpolation::Slerp);
        QVERIFY(c.path.constantSpeed);
        QCOMPARE(c.path.keys.size(), std::size_t(2));
        QCOMPARE(c.path.keys[1].time, 2.5);
        QCOMPARE(c.path.keys[1].position, glm::dvec3(0.1, 1, 5)); // doubles, exactly
        QCOMPARE(c.path.keys[1].orientation, glm::dquat(0.8, 0, 0.6, 0));
        QCOMPARE(c.path.keys[0].yfov, 0.5f);
        QCOMPARE(c.path.keys[0].focusDistance, 3.0f);
        QCOMPARE(c.path.keys[0].lensRadius, 0.01f);
    }

    void cameraPathKeysMustIncrease()
    {
        Json doc = triangle().finish();
        doc["cameras"] = Json::parse(R"([{"type": "perspective", "perspective": {"yfov": 0.5, "znear": 0.1}}])");
        doc["nodes"][0] = Json::parse(R"({"camera": 0, "extensions": {"GLINT_camera_path": {"keys": [{"t": 1}, {"t": 1}]}}})");
        GLINT_EXPECT_ERROR(loadJson(doc), "invalid-camera-path", "keys[1].t must be greater");
    }

    void shapeReplacesItsFallbackMesh()
    {
        Json doc = triangle().finish();
        doc["materials"] = Json::array({{{"name", "m"}}});
        doc["meshes"][0]["extensions"]["GLINT_shape_fallback"] = Json::object();
        doc["nodes"][0]["extensions"]["GLINT_shape"] = {{"kind", "cylinder"}, {"radius", 0.25}, {"size", {1, 2, 3}}, {"height", 3}, {"material", 0}};
        const Scene scene = loadJson(doc).scene;
        QVERIFY(scene.meshes.empty());
        const Shape s = *scene.at(NodeId{1}).get<Shape>();
        QCOMPARE(s.kind, ShapeKind::Cylinder);
        QCOMPARE(s.radius, 0.25f);
        QCOMPARE(s.size, glm::vec3(1, 2, 3));
        QCOMPARE(s.height, 3.0f);
        QCOMPARE(s.material, scene.materials.begin()->first);
        QVERIFY(scene.at(NodeId{1}).unknown.is_null());
    }

    void materialsWithExtensionsAndTextureTransform()
    {
        Json doc = triangle().finish();
        doc["images"] = Json::array({{{"uri", "data:image/png;base64," + base64(pngHeader(2, 2))}}});
        doc["samplers"] = Json::array({{{"magFilter", 9728}, {"minFilter", 9987}, {"wrapS", 33071}, {"wrapT", 33648}, {"extras", {{"s", 1}}}}});
        doc["textures"] = Json::array({{{"source", 0}, {"sampler", 0}, {"name", "t"}}});
        doc["materials"] = Json::parse(R"([{"name": "glass", "alphaMode": "MASK", "alphaCutoff": 0.3, "doubleSided": true, "emissiveFactor": [1, 0.5, 0],
            "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.25, 1, 0.75], "metallicFactor": 0.1, "roughnessFactor": 0.2,
              "baseColorTexture": {"index": 0, "texCoord": 1, "extensions": {"KHR_texture_transform": {"offset": [0.5, 0], "rotation": 1.5, "scale": [2, 3], "texCoord": 0}, "EXT_other": {"x": 1}}}},
            "normalTexture": {"index": 0, "scale": 0.5}, "occlusionTexture": {"index": 0, "strength": 0.7},
            "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 5}, "KHR_materials_specular": {"specularFactor": 0.3, "specularColorFactor": [1, 0.9, 0.8]},
              "KHR_materials_transmission": {"transmissionFactor": 0.9}, "KHR_materials_ior": {"ior": 1.33},
              "KHR_materials_volume": {"thicknessFactor": 0.1, "attenuationDistance": 2, "attenuationColor": [0.9, 1, 1]},
              "KHR_materials_clearcoat": {"clearcoatFactor": 1}}, "extras": {"note": "kept"}}])");
        const Scene scene = loadJson(doc).scene;
        const Material& m = scene.materials.begin()->second;
        QCOMPARE(m.alphaMode, AlphaMode::Mask);
        QCOMPARE(m.alphaCutoff, 0.3f);
        QVERIFY(m.doubleSided);
        QCOMPARE(m.baseColorFactor, glm::vec4(0.5f, 0.25f, 1, 0.75f));
        QCOMPARE(m.metallicFactor, 0.1f);
        QCOMPARE(m.roughnessFactor, 0.2f);
        QCOMPARE(m.emissiveFactor, glm::vec3(1, 0.5f, 0));
        QCOMPARE(m.emissiveStrength, 5.0f);
        QCOMPARE(m.specularFactor, 0.3f);
        QCOMPARE(m.specularColorFactor, glm::vec3(1, 0.9f, 0.8f));
        QCOMPARE(m.transmissionFactor, 0.9f);
        QCOMPARE(m.ior, 1.33f);
        QCOMPARE(m.thicknessFactor, 0.1f);
        QCOMPARE(m.attenuationDistance, 2.0f);
        QCOMPARE(m.attenuationColor, glm::vec3(0.9f, 1, 1));
        QCOMPARE(m.normalTexture.scale, 0.5f);
        QCOMPARE(m.occlusionTexture.scale, 0.7f);
        QCOMPARE(m.baseColorTexture.texCoord, 1);
        QCOMPARE(m.baseColorTexture.transform.offset, glm::vec2(0.5f, 0));
        QCOMPARE(m.baseColorTexture.transform.rotation, 1.5f);
        QCOMPARE(m.baseColorTexture.transform.scale, glm::vec2(2, 3));
        QCOMPARE(m.baseColorTexture.transform.texCoord, 0);
        QCOMPARE(jsonText(m.baseColorTexture.unknown), jsonText(Json::parse(R"({"extensions": {"EXT_other": {"x": 1}}})")));
        QCOMPARE(jsonText(m.unknown), jsonText(Json::parse(R"({"extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": 1}}, "extras": {"note": "kept"}})")));
        const Sampler& s = scene.samplers.begin()->second;
        QCOMPARE(s.magFilter, Filter::Nearest);
        QCOMPARE(s.minFilter, Filter::LinearMipmapLinear);
        QCOMPARE(s.wrapS, Wrap::ClampToEdge);
        QCOMPARE(s.wrapT, Wrap::MirroredRepeat);
        QCOMPARE(jsonText(s.unknown), jsonText(Json::parse(R"({"extras": {"s": 1}})")));
        QCOMPARE(scene.textures.begin()->second.sampler, scene.samplers.begin()->first);
    }

    // The textures of KHR_materials_specular, _transmission and _volume: read with their texCoord,
    // KHR_texture_transform and unknown textureInfo extensions, and not named as dropped.
    void extensionTexturesAreReadAndNotDropped()
    {
        Json doc = triangle().finish();
        doc["images"] = Json::array({{{"uri", "data:image/png;base64," + base64(pngHeader(2, 2))}}});
        doc["textures"] = Json::array({{{"source", 0}}, {{"source", 0}}});
        doc["materials"] = Json::parse(R"([{"extensions": {
            "KHR_materials_specular": {"specularTexture": {"index": 0, "texCoord": 1},
              "specularColorTexture": {"index": 1, "extensions": {"KHR_texture_transform": {"offset": [0.25, 0.5], "rotation": 0.5, "scale": [2, 4], "texCoord": 1}}}},
            "KHR_materials_transmission": {"transmissionFactor": 1, "transmissionTexture": {"index": 1, "extensions": {"EXT_other": {"y": 2}}}},
            "KHR_materials_volume": {"thicknessFactor": 0.5, "thicknessTexture": {"index": 0, "texCoord": 1, "extensions": {"KHR_texture_transform": {"scale": [3, 3]}}}}}}])");
        const LoadResult r = loadJson(doc);
        const Material& m = r.scene.materials.begin()->second;
        const auto texture = [&](int index) { return std::next(r.scene.textures.begin(), index)->first; };
        QCOMPARE(m.specularTexture.texture, texture(0));
        QCOMPARE(m.specularTexture.texCoord, 1);
        QCOMPARE(m.specularColorTexture.texture, texture(1));
        QCOMPARE(m.specularColorTexture.transform.offset, glm::vec2(0.25f, 0.5f));
        QCOMPARE(m.specularColorTexture.transform.rotation, 0.5f);
        QCOMPARE(m.specularColorTexture.transform.scale, glm::vec2(2, 4));
        QCOMPARE(m.specularColorTexture.transform.texCoord, 1);
        QCOMPARE(m.transmissionTexture.texture, texture(1));
        QCOMPARE(jsonText(m.transmissionTexture.unknown), jsonText(Json::parse(R"({"extensions": {"EXT_other": {"y": 2}}})")));
        QCOMPARE(m.thicknessTexture.texture, texture(0));
        QCOMPARE(m.thicknessTexture.texCoord, 1);
        QCOMPARE(m.thicknessTexture.transform.scale, glm::vec2(3, 3));
        QVERIFY(m.unknown.is_null() || m.unknown.empty());
        QVERIFY(!hasWarning(r.warnings, "extension-dropped"));
        QVERIFY(r.scene.unsupported.empty());
    }

    // Glint's own volume scattering: read into the material, not kept as unknown, not named as
    // dropped; its own nested extensions and extras are named (the object is rebuilt on save).
    void volumeScatterIsRead()
    {
        Json doc = triangle().finish();
        doc["materials"] = Json::parse(R"([{"extensions": {
            "KHR_materials_volume": {"thicknessFactor": 0.2, "attenuationDistance": 0.5, "attenuationColor": [0.8, 0.9, 1]},
            "GLINT_materials_volume_scatter": {"scatterColor": [0.9, 0.5, 0.25], "scatterAnisotropy": -0.6}}},
          {"extensions": {"GLINT_materials_volume_scatter": {"scatterAnisotropy": 0.3, "extras": {"x": 1}}}},
          {"extensions": {"GLINT_materials_volume_scatter": {}}}])");
        const LoadResult r = loadJson(doc);
        QCOMPARE(r.scene.materials.size(), std::size_t(3));
        auto it = r.scene.materials.begin();
        const Material& full = (it++)->second;
        QCOMPARE(full.scatterColor, glm::vec3(0.9f, 0.5f, 0.25f));
        QCOMPARE(full.scatterAnisotropy, -0.6f);
        QCOMPARE(full.attenuationDistance, 0.5f);
        QVERIFY(full.unknown.is_null() || full.unknown.empty());
        const Material& partial = (it++)->second;
        QCOMPARE(partial.scatterColor, glm::vec3(0.0f)); // the default where a key is left out
        QCOMPARE(partial.scatterAnisotropy, 0.3f);
        const Material& empty = it->second;
        QVERIFY(empty == Material{});
        std::vector<std::string> dropped;
        for (const Warning& w : r.scene.unsupported)
            if (w.code == "extension-dropped") dropped.push_back(w.message);
        QCOMPARE(dropped.size(), std::size_t(1));
        QCOMPARE(QString::fromStdString(dropped[0]),
                 QStringLiteral("materials[1].extensions.GLINT_materials_volume_scatter has extras, which Glint does not keep"));
        QVERIFY(!hasWarning(r.warnings, "invalid-value"));
    }

    void unknownContentIsKeptVerbatim()
    {
        Json doc = triangle().finish();
        doc["asset"]["copyright"] = "CC0";
        doc["asset"]["generator"] = "someone";
        doc["extensions"]["EXT_top"] = {{"a", 1}};
        doc["extras"] = {{"top", true}};
        doc["nodes"][0]["extensions"]["EXT_node"] = {{"b", 2}};
        doc["nodes"][0]["extras"] = "n";
        doc["meshes"][0]["extras"] = {{"m", 1}};
        doc["meshes"][0]["primitives"][0]["extensions"]["EXT_prim"] = Json::object();
        const Scene scene = loadJson(doc).scene;
        QCOMPARE(jsonText(scene.unknown), jsonText(Json::parse(R"({"asset": {"copyright": "CC0"}, "extensions": {"EXT_top": {"a": 1}}, "extras": {"top": true}})")));
        QCOMPARE(jsonText(scene.at(NodeId{1}).unknown), jsonText(Json::parse(R"({"extensions": {"EXT_node": {"b": 2}}, "extras": "n"})")));
        QCOMPARE(jsonText(scene.meshes.begin()->second.unknown), jsonText(Json::parse(R"({"extras": {"m": 1}})")));
        QCOMPARE(jsonText(scene.meshes.begin()->second.primitives[0].unknown), jsonText(Json::parse(R"({"extensions": {"EXT_prim": {}}})")));
    }

    void extensionsOnRebuiltObjectsAreNamedAsDropped()
    {
        Json doc = withLights(triangle().finish(), Json::array({{{"type", "point"}, {"extras", {{"rig", 1}}}}}));
        doc["cameras"] = Json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}, {"extensions", {{"EXT_lens", Json::object()}}}}}}});
        doc["materials"] = Json::array({{{"pbrMetallicRoughness", {{"extras", {{"baked", true}}}}}}});
        doc["nodes"].push_back({{"camera", 0}});
        doc["scenes"][0]["nodes"].push_back(1);
        const LoadResult r = loadJson(doc);
        std::vector<std::string> messages;
        for (const Warning& w : r.scene.unsupported)
            if (w.code == "extension-dropped") messages.push_back(w.message);
        std::sort(messages.begin(), messages.end());
        QCOMPARE(messages.size(), std::size_t(3));
        QCOMPARE(QString::fromStdString(messages[0]), QStringLiteral("cameras[0].perspective has extension EXT_lens, which Glint does not keep"));
        QCOMPARE(QString::fromStdString(messages[1]), QStringLiteral("extensions.KHR_lights_punctual.lights[0] has extras, which Glint does not keep"));
        QCOMPARE(QString::fromStdString(messages[2]), QStringLiteral("materials[0].pbrMetallicRoughness has extras, which Glint does not keep"));
        QVERIFY(hasWarning(r.warnings, "extension-dropped"));
    }

    void manyDroppedPlacesAreSummedUp()
    {
        Json doc = triangle().finish();
        for (int i = 0; i < 20; ++i) doc["accessors"].push_back(doc["accessors"][0]);
        for (Json& accessor : doc["accessors"]) accessor["extras"] = {{"x", 1}};
        const LoadResult r = loadJson(doc);
        const auto dropped = std::count_if(r.scene.unsupported.begin(), r.scene.unsupported.end(), [](const Warning& w) { return w.code == "extension-dropped"; });
        QCOMPARE(dropped, 17); // 16 named, then one line for the rest
        QVERIFY(QString::fromStdString(r.scene.unsupported.back().message).startsWith(QStringLiteral("6 more objects")));
    }

    void trsAnimationsAreKept()
    {
        GltfBuilder b = triangle();
        const int times = b.accessor(std::vector<float>{0, 1}, 5126, "SCALAR", 1);
        const int moves = b.accessor(std::vector<float>{0, 0, 0, 1, 2, 3}, 5126, "VEC3", 3);
        const int turns = b.accessor(std::vector<std::int16_t>{0, 0, 0, 32767, 0, 32767, 0, 0}, 5122, "VEC4", 4, true);
        b.doc["animations"] = Json::array({{{"name", "go"}, {"extras", 1},
            {"samplers", {{{"input", times}, {"output", moves}, {"interpolation", "STEP"}}, {{"input", times}, {"output", turns}}, {{"input", times}, {"output", times}}}},
            {"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}},
                          {{"sampler", 1}, {"target", {{"node", 0}, {"path", "rotation"}}}},
                          {{"sampler", 2}, {"target", {{"node", 0}, {"path", "weights"}}}}}}}});
        const LoadResult r = loadJson(b.finish());
        QCOMPARE(r.scene.animations.size(), std::size_t(1));
        const Animation& a = r.scene.animations.begin()->second;
        QCOMPARE(QString::fromStdString(a.name), QStringLiteral("go"));
        QCOMPARE(jsonText(a.unknown), jsonText(Json::parse(R"({"extras": 1})")));
        QCOMPARE(a.channels.size(), std::size_t(2));
        QCOMPARE(a.channels[0].node, NodeId{1});
        QCOMPARE(a.channels[0].interpolation, Interpolation::Step);
        QCOMPARE(a.channels[0].times, (std::vector<float>{0, 1}));
        QCOMPARE(a.channels[0].values, (std::vector<float>{0, 0, 0, 1, 2, 3}));
        QCOMPARE(a.channels[1].path, AnimationPath::Rotation);
        QCOMPARE(a.channels[1].values, (std::vector<float>{0, 0, 0, 1, 0, 1, 0, 0}));
        QVERIFY(hasWarning(r.warnings, "animation-channel-dropped"));
        QCOMPARE(QString::fromStdString(r.scene.unsupported.at(0).code), QStringLiteral("animation-channel-dropped"));
    }

    void animationCountMismatch()
    {
        GltfBuilder b = triangle();
        const int times = b.accessor(std::vector<float>{0, 1, 2}, 5126, "SCALAR", 1);
        const int moves = b.accessor(std::vector<float>{0, 0, 0, 1, 2, 3}, 5126, "VEC3", 3);
        b.doc["animations"] = Json::array({{{"samplers", {{{"input", times}, {"output", moves}}}}, {"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "scale"}}}}}}}});
        GLINT_EXPECT_ERROR(loadJson(b.finish()), "animation-count-mismatch", "has 3 times but 2 values");
    }

    void bakedCameraPathAnimationIsDropped()
    {
        GltfBuilder b = triangle();
        const int times = b.accessor(std::vector<float>{0, 1}, 5126, "SCALAR", 1);
        const int moves = b.accessor(std::vector<float>{0, 0, 0, 1, 2, 3}, 5126, "VEC3", 3);
        b.doc["animations"] = Json::array({{{"extensions", {{"GLINT_baked_camera_path", Json::object()}}},
            {"samplers", {{{"input", times}, {"output", moves}}}}, {"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}}}}}});
        const LoadResult r = loadJson(b.finish());
        QVERIFY(r.scene.animations.empty());
        QVERIFY(r.warnings.empty());
    }

    void skinsAreNamedAsDropped()
    {
        Json doc = threeNodes(0, 0, 0);
        doc["skins"] = Json::array({{{"joints", {1}}}});
        doc["nodes"][0]["skin"] = 0;
        const LoadResult r = loadJson(doc);
        QVERIFY(r.scene.at(NodeId{1}).get<MeshInstance>());
        QVERIFY(hasWarning(r.warnings, "skin-dropped"));
        QCOMPARE(r.scene.unsupported.size(), std::size_t(2)); // the skinned node and the skins
    }
};

QTEST_APPLESS_MAIN(TestGltfReadScene)
#include "test_gltf_read_scene.moc"
