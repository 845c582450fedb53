// Primitives become indexed float triangle lists: topology conversion, normalized integers, colours,
// generated normals and tangents, repaired normals.
#include "io_read_helpers.h"

#include <QTest>

using namespace glint;
using namespace glint::test;

namespace {

const Primitive& firstPrimitive(const LoadResult& r) { return r.scene.meshes.begin()->second.primitives.at(0); }

// The position at every corner, in triangle order: independent of how vertices were split.
std::vector<glm::vec3> corners(const Primitive& p)
{
    std::vector<glm::vec3> out;
    for (std::uint32_t i : p.indices) out.push_back(p.positions.at(i));
    return out;
}

const glm::vec3 v0{0, 0, 0}, v1{1, 0, 0}, v2{0, 1, 0}, v3{1, 1, 0};

// Four vertices of a unit quad in the XY plane, no indices, in the given mode.
GltfBuilder quadWithMode(int mode)
{
    GltfBuilder b;
    const int p = b.positions({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0});
    b.doc["meshes"] = Json::array({{{"primitives", {{{"attributes", {{"POSITION", p}}}, {"mode", mode}}}}}});
    return b;
}

} // namespace

class TestGltfReadGeometry : public QObject {
    Q_OBJECT

private slots:
    void nonIndexedGetsSequentialIndices()
    {
        const LoadResult r = loadJson(quadWithMode(4).finish());
        QCOMPARE(corners(firstPrimitive(r)), (std::vector<glm::vec3>{v0, v1, v2})); // the 4th vertex makes no triangle
    }

    void stripBecomesList()
    {
        const LoadResult r = loadJson(quadWithMode(5).finish());
        QCOMPARE(corners(firstPrimitive(r)), (std::vector<glm::vec3>{v0, v1, v2, v2, v1, v3}));
    }

    void fanBecomesList()
    {
        const LoadResult r = loadJson(quadWithMode(6).finish());
        QCOMPARE(corners(firstPrimitive(r)), (std::vector<glm::vec3>{v0, v1, v2, v0, v2, v3}));
    }

    void pointsAndLinesAreSkippedWithWarning()
    {
        for (int mode : {0, 1, 2, 3}) {
            const LoadResult r = loadJson(quadWithMode(mode).finish());
            QVERIFY(r.scene.meshes.begin()->second.primitives.empty());
            QVERIFY(hasWarning(r.warnings, "primitive-skipped"));
            QCOMPARE(r.scene.unsupported.size(), std::size_t(1));
        }
    }

    void missingNormalsBecomeFlat()
    {
        const LoadResult r = loadJson(triangle().finish());
        QCOMPARE(firstPrimitive(r).normals, (std::vector<glm::vec3>(3, glm::vec3(0, 0, 1))));
    }

    void zeroLengthNormalsAreRepaired()
    {
        GltfBuilder b = triangle();
        b.primitive()["attributes"]["NORMAL"] = b.accessor(std::vector<float>{0, 0, 1, 0, 0, 0, 0, 0, 1}, 5126, "VEC3", 3);
        const LoadResult r = loadJson(b.finish());
        QCOMPARE(firstPrimitive(r).normals[1], glm::vec3(0, 0, 1));
        QCOMPARE(QString::fromStdString(findWarning(r.warnings, "zero-normal")->message),
                 QStringLiteral("primitive 0 of mesh 0: 1 normals of zero length replaced by face normals"));
    }

    void normalizedUnsignedTexcoords()
    {
        GltfBuilder b = triangle();
        b.primitive()["attributes"]["TEXCOORD_0"] = b.accessor(std::vector<std::uint8_t>{0, 255, 51, 102, 255, 0}, 5121, "VEC2", 2, true);
        b.primitive()["attributes"]["TEXCOORD_1"] = b.accessor(std::vector<std::uint16_t>{0, 65535, 13107, 0, 65535, 65535}, 5123, "VEC2", 2, true);
        const LoadResult r = loadJson(b.finish());
        const Primitive& p = firstPrimitive(r);
        QCOMPARE(p.uv0, (std::vector<glm::vec2>{{0, 1}, {0.2f, 0.4f}, {1, 0}}));
        QCOMPARE(p.uv1, (std::vector<glm::vec2>{{0, 1}, {0.2f, 0}, {1, 1}}));
    }

    void normalizedSignedClampsAtMinusOne()
    {
        GltfBuilder b = triangle();
        b.primitive()["attributes"]["TEXCOORD_0"] = b.accessor(std::vector<std::int8_t>{-128, -127, 127, 0, 0, 0}, 5120, "VEC2", 2, true);
        QCOMPARE(firstPrimitive(loadJson(b.finish())).uv0[0], glm::vec2(-1, -1));
    }

    void colorAsVec3GetsOpaqueAlpha()
    {
        GltfBuilder b = triangle();
        b.primitive()["attributes"]["COLOR_0"] = b.accessor(std::vector<std::uint8_t>{255, 0, 0, 0, 0, 255, 0, 0, 0, 0, 255, 0}, 5121, "VEC4", 4, true);
        QCOMPARE(firstPrimitive(loadJson(b.finish())).colors[0], glm::vec4(1, 0, 0, 0));
        b = triangle();
        b.primitive()["attributes"]["COLOR_0"] = b.accessor(std::vector<float>{1, 0, 0, 0, 1, 0, 0, 0, 1}, 5126, "VEC3", 3);
        QCOMPARE(firstPrimitive(loadJson(b.finish())).colors[2], glm::vec4(0, 0, 1, 1));
    }

    void attributeCountMismatch()
    {
        GltfBuilder b = triangle();
        b.primitive()["attributes"]["NORMAL"] = b.accessor(std::vector<float>{0, 0, 1}, 5126, "VEC3", 3);
        GLINT_EXPECT_ERROR(loadJson(b.finish()), "attribute-count-mismatch", "NORMAL of primitive 0 of mesh 0 has 1 elements, POSITION has 3");
    }

    void sparseAccessorOverridesValues()
    {
        GltfBuilder b = triangle();
        const int indices = b.view(std::vector<std::uint8_t>{2});
        const int values = b.view(std::vector<float>{5, 6, 7});
        b.doc["accessors"][0]["sparse"] = {{"count", 1}, {"indices", {{"bufferView", indices}, {"componentType", 5121}}}, {"values", {{"bufferView", values}}}};
        QCOMPARE(firstPrimitive(loadJson(b.finish())).positions, (std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0}, {5, 6, 7}}));
    }

    void normalMappedMaterialGetsTangents()
    {
        GltfBuilder b = triangle();
        b.primitive()["attributes"]["TEXCOORD_0"] = b.accessor(std::vector<float>{0, 0, 1, 0, 0, 1}, 5126, "VEC2", 2);
        b.primitive()["material"] = 0;
        const std::vector<std::uint8_t> png = pngHeader(4, 4);
        b.doc["images"] = Json::array({{{"uri", "data:image/png;base64," + base64(png)}}});
        b.doc["textures"] = Json::array({{{"source", 0}}});
        b.doc["materials"] = Json::array({{{"normalTexture", {{"index", 0}}}}});
        const LoadResult r = loadJson(b.finish());
        const Primitive& p = firstPrimitive(r);
        // u along +X, v along +Y, normal +Z: tangent +X. glTF's v runs down the image, so the
        // bitangent cross(N, T) * w = +Y needs handedness -1.
        QCOMPARE(p.tangents.size(), std::size_t(3));
        QVERIFY(glm::all(glm::epsilonEqual(p.tangents[0], glm::vec4(1, 0, 0, -1), 1e-5f)));
    }

    void noTangentsWithoutNormalMap()
    {
        GltfBuilder b = triangle();
        b.primitive()["attributes"]["TEXCOORD_0"] = b.accessor(std::vector<float>{0, 0, 1, 0, 0, 1}, 5126, "VEC2", 2);
        QVERIFY(firstPrimitive(loadJson(b.finish())).tangents.empty());
    }

    void morphTargetsAreNamedAsDropped()
    {
        GltfBuilder b = triangle();
        b.primitive()["targets"] = Json::array({{{"POSITION", 0}}});
        const LoadResult r = loadJson(b.finish());
        QCOMPARE(firstPrimitive(r).positions.size(), std::size_t(3));
        QCOMPARE(QString::fromStdString(r.scene.unsupported.at(0).code), QStringLiteral("morph-targets-dropped"));
    }

    // Non-zero default weights: the shape glTF viewers show without animation, w0 * t0 + w1 * t1
    // added to the base positions and normals (Blender writes shape key values there).
    void morphTargetsApplyTheDefaultWeights()
    {
        GltfBuilder b = triangle();
        b.primitive()["attributes"]["NORMAL"] = b.positions({0, 0, 1, 0, 0, 1, 0, 0, 1});
        const int lift = b.positions({0, 0, 2, 0, 0, 0, 0, 0, 0});
        const int shift = b.positions({1, 0, 0, 1, 0, 0, 1, 0, 0});
        const int tilt = b.positions({0, 1, 0, 0, 0, 0, 0, 0, 0});
        b.primitive()["targets"] = Json::array({{{"POSITION", lift}, {"NORMAL", tilt}}, {{"POSITION", shift}}});
        b.doc["meshes"][0]["weights"] = {0.5, 0.25};
        const LoadResult r = loadJson(b.finish());
        const Primitive& p = firstPrimitive(r);
        QCOMPARE(p.positions[0], glm::vec3(0.25f, 0.0f, 1.0f));
        QCOMPARE(p.positions[1], glm::vec3(1.25f, 0.0f, 0.0f));
        QCOMPARE(p.positions[2], glm::vec3(0.25f, 1.0f, 0.0f));
        QCOMPARE(p.normals[0], glm::vec3(0.0f, 0.5f, 1.0f));
        QCOMPARE(p.normals[1], glm::vec3(0.0f, 0.0f, 1.0f));
        QCOMPARE(QString::fromStdString(r.scene.unsupported.at(0).message),
                 QStringLiteral("mesh 0 has morph targets: loaded as its shape at the default weights (0.5, 0.25), static"));
    }

    void morphWeightsOfANodeAreNamed()
    {
        GltfBuilder b = triangle();
        const int lift = b.positions({0, 0, 1, 0, 0, 1, 0, 0, 1});
        b.primitive()["targets"] = Json::array({{{"POSITION", lift}}});
        b.doc["meshes"][0]["weights"] = {1.0};
        b.doc["nodes"][0]["weights"] = {1.0};
        QVERIFY(!hasWarning(loadJson(b.finish()).warnings, "morph-weights-ignored")); // the same as the mesh's
        b.doc["nodes"][0]["weights"] = {0.5};
        const LoadResult r = loadJson(b.finish());
        QVERIFY(hasWarning(r.warnings, "morph-weights-ignored"));
        QCOMPARE(firstPrimitive(r).positions[0], glm::vec3(0.0f, 0.0f, 1.0f)); // the mesh's weight 1
    }

    void morphWeightBeyondFloatRangeIsRefused()
    {
        GltfBuilder b = triangle();
        b.primitive()["targets"] = Json::array({{{"POSITION", 0}}});
        b.doc["meshes"][0]["weights"] = {1e39};
        GLINT_EXPECT_ERROR(loadJson(b.finish()), "non-finite-value", "meshes[0].weights[0]");
    }

    void morphTargetOfTheWrongLengthIsRefused()
    {
        GltfBuilder b = triangle();
        const int two = b.positions({0, 0, 1, 0, 0, 1});
        b.primitive()["targets"] = Json::array({{{"POSITION", two}}});
        b.doc["meshes"][0]["weights"] = {1.0};
        GLINT_EXPECT_ERROR(loadJson(b.finish()), "attribute-count-mismatch", "POSITION displacement of morph target 0 of primitive 0 of mesh 0");
    }
};

QTEST_APPLESS_MAIN(TestGltfReadGeometry)
#include "test_gltf_read_geometry.moc"
