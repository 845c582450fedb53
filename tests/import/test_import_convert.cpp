// The Assimp -> glint conversion, in-process (no worker): geometry counts, units and axes,
// Phong and PBR material mapping, textures and their folder confinement, limits.
#include "import_test_util.h"
#include "obj_reference.h"

#include "scene/import/assimp_convert.h"
#include "scene/import/assimp_materials.h"
#include "scene/import/assimp_read.h"

#include <assimp/camera.h>
#include <assimp/light.h>
#include <assimp/material.h>
#include <assimp/scene.h>

#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <memory>

using namespace glint;
using namespace glint::test;

namespace {

const std::filesystem::path kData = GLINT_TEST_DATA_DIR;

bool near(glm::vec3 a, glm::vec3 b, float tolerance = 1e-5f) { return glm::all(glm::lessThanEqual(glm::abs(a - b), glm::vec3(tolerance))); }

const Material& onlyMaterialOfFirstMesh(const Scene& scene) {
    return scene.materials.at(scene.meshes.begin()->second.primitives.front().material);
}

// A one-mesh Assimp scene built by hand: positions and triangles.
std::unique_ptr<aiScene> meshScene(const std::vector<aiVector3D>& positions, const std::vector<std::array<unsigned, 3>>& triangles) {
    auto scene = std::make_unique<aiScene>();
    auto* mesh = new aiMesh;
    mesh->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
    mesh->mNumVertices = static_cast<unsigned>(positions.size());
    mesh->mVertices = new aiVector3D[positions.size()];
    std::copy(positions.begin(), positions.end(), mesh->mVertices);
    mesh->mNumFaces = static_cast<unsigned>(triangles.size());
    mesh->mFaces = new aiFace[triangles.size()];
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        mesh->mFaces[i].mNumIndices = 3;
        mesh->mFaces[i].mIndices = new unsigned[3]{triangles[i][0], triangles[i][1], triangles[i][2]};
    }
    scene->mNumMeshes = 1;
    scene->mMeshes = new aiMesh*[1]{mesh};
    scene->mNumMaterials = 1;
    scene->mMaterials = new aiMaterial*[1]{new aiMaterial};
    scene->mRootNode = new aiNode("root");
    scene->mRootNode->mNumMeshes = 1;
    scene->mRootNode->mMeshes = new unsigned[1]{0};
    return scene;
}

// One triangle with FBX-style metadata: a Z-up file in centimetres.
std::unique_ptr<aiScene> zUpCentimetreTriangle() {
    auto scene = meshScene({{0, 0, 0}, {0, 100, 0}, {0, 0, 100}}, {{0, 1, 2}});
    scene->mMetaData = aiMetadata::Alloc(7);
    scene->mMetaData->Set(0, "UpAxis", std::int32_t(2));
    scene->mMetaData->Set(1, "UpAxisSign", std::int32_t(1));
    scene->mMetaData->Set(2, "FrontAxis", std::int32_t(1));
    scene->mMetaData->Set(3, "FrontAxisSign", std::int32_t(-1));
    scene->mMetaData->Set(4, "CoordAxis", std::int32_t(0));
    scene->mMetaData->Set(5, "CoordAxisSign", std::int32_t(1));
    scene->mMetaData->Set(6, "UnitScaleFactor", 1.0);
    return scene;
}

// meshScene plus a child node "rig" that holds `cameras` and `lights` (linked by name, as Assimp does).
void addRig(aiScene& scene, std::vector<aiCamera*> cameras, std::vector<aiLight*> lights) {
    auto* rig = new aiNode("rig");
    rig->mTransformation = aiMatrix4x4(aiVector3D(1, 1, 1), aiQuaternion(), aiVector3D(0, 0, 5));
    rig->mParent = scene.mRootNode;
    scene.mRootNode->mNumChildren = 1;
    scene.mRootNode->mChildren = new aiNode*[1]{rig};
    for (aiCamera* c : cameras) c->mName = "rig";
    for (aiLight* l : lights) l->mName = "rig";
    scene.mNumCameras = static_cast<unsigned>(cameras.size());
    scene.mCameras = cameras.empty() ? nullptr : new aiCamera*[cameras.size()];
    std::copy(cameras.begin(), cameras.end(), scene.mCameras);
    scene.mNumLights = static_cast<unsigned>(lights.size());
    scene.mLights = lights.empty() ? nullptr : new aiLight*[lights.size()];
    std::copy(lights.begin(), lights.end(), scene.mLights);
}

const Node& nodeNamed(const Scene& scene, const std::string& name) { return scene.at(*scene.findByName(name)); }

glm::vec3 worldAxis(const Scene& scene, const std::string& name, glm::vec4 axis) {
    return glm::normalize(glm::vec3(scene.worldFromNode(*scene.findByName(name)) * axis));
}

} // namespace

class TestImportConvert : public QObject {
    Q_OBJECT

private slots:
    void bunnyHasTheFilesTrianglesAndDistinctVertices() {
        const auto file = kData / "meshes/stanford-bunny.obj";
        const ObjCounts expected = countObj(file);
        QCOMPARE(expected.triangles, std::size_t(69451));
        LoadResult r = readWithAssimp(file, {file});
        QCOMPARE(r.scene.meshes.size(), std::size_t(1));
        QCOMPARE(totalTriangles(r.scene), expected.triangles);
        QCOMPARE(totalVertices(r.scene), expected.distinctPositions);
        const Primitive& p = r.scene.meshes.begin()->second.primitives.front();
        QCOMPARE(p.normals.size(), p.positions.size()); // generated: the file has none
        for (glm::vec3 n : p.normals) QVERIFY(std::abs(glm::length(n) - 1.0f) < 1e-3f);
        QVERIFY(p.uv0.empty());
    }

    void teapotHasTheFilesTrianglesAndDistinctVertices() {
        const auto file = kData / "meshes/utah-teapot.obj";
        const ObjCounts expected = countObj(file);
        LoadResult r = readWithAssimp(file, {file});
        QCOMPARE(totalTriangles(r.scene), std::size_t(6320));
        QCOMPARE(totalTriangles(r.scene), expected.triangles);
        QCOMPARE(totalVertices(r.scene), expected.distinctPositions);
    }

    void spotKeepsItsTextureBytesAndUvs() {
        QTemporaryDir dir;
        const std::filesystem::path folder = dir.path().toStdString();
        std::filesystem::copy_file(kData / "meshes/spot/spot_texture.png", folder / "spot_texture.png");
        writeText(folder / "spot.mtl", "newmtl spot\nKd 1 1 1\nNs 0\nmap_Kd spot_texture.png\n");
        std::ifstream original(kData / "meshes/spot/spot_triangulated.obj");
        writeText(folder / "spot.obj", "mtllib spot.mtl\nusemtl spot\n" + std::string(std::istreambuf_iterator<char>(original), {}));

        LoadResult r = readWithAssimp(folder / "spot.obj", {folder / "spot.obj"});
        QCOMPARE(totalTriangles(r.scene), std::size_t(5856));
        const Primitive& p = r.scene.meshes.begin()->second.primitives.front();
        QCOMPARE(p.uv0.size(), p.positions.size());
        // glTF's texture origin is the top left, OBJ's the bottom left: v becomes 1 - v.
        const auto [fileMin, fileMax] = objUvBounds(kData / "meshes/spot/spot_triangulated.obj");
        glm::vec2 lo(1e9f), hi(-1e9f);
        for (glm::vec2 uv : p.uv0) lo = glm::min(lo, uv), hi = glm::max(hi, uv);
        QVERIFY(std::abs(lo.x - fileMin.x) < 1e-6f && std::abs(hi.x - fileMax.x) < 1e-6f);
        QVERIFY(std::abs(lo.y - (1.0f - fileMax.y)) < 1e-6f && std::abs(hi.y - (1.0f - fileMin.y)) < 1e-6f);
        const Material& m = r.scene.materials.at(p.material);
        QVERIFY(m.baseColorTexture.valid());
        const Image& image = r.scene.images.at(r.scene.textures.at(m.baseColorTexture.texture).image);
        QCOMPARE(image.mimeType, std::string("image/png"));
        QVERIFY(!image.missing);
        QVERIFY(image.encoded == readBytes(kData / "meshes/spot/spot_texture.png"));
        QVERIFY(r.warnings.empty());
    }

    void phongMaterialMapsToMetallicRoughness() {
        QTemporaryDir dir;
        const std::filesystem::path folder = std::filesystem::path(dir.path().toStdString()) / "model";
        std::filesystem::create_directory(folder);
        writeText(folder.parent_path() / "outside.png", "\x89PNG\r\n\x1a\n");
        writeText(folder / "m.mtl", "newmtl shiny\nKd 0.5 0.25 0.125\nKs 0.5 0.5 0.25\nNs 98\nd 0.25\nKe 2 1 0\n"
                                    "map_Kd missing.png\nmap_Ks ../outside.png\n");
        writeText(folder / "m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl shiny\nf 1 2 3\n");

        LoadResult r = readWithAssimp(folder / "m.obj", {folder / "m.obj"});
        const Material& m = onlyMaterialOfFirstMesh(r.scene);
        QCOMPARE(m.name, std::string("shiny"));
        QVERIFY(near(glm::vec3(m.baseColorFactor), {0.5f, 0.25f, 0.125f}));
        QCOMPARE(m.baseColorFactor.w, 1.0f);
        QCOMPARE(m.metallicFactor, 0.0f);
        QVERIFY(std::abs(m.roughnessFactor - std::sqrt(2.0f / 100.0f)) < 1e-6f);
        QVERIFY(std::abs(m.specularFactor - 0.5f) < 1e-6f);
        QVERIFY(near(m.specularColorFactor, {1.0f, 1.0f, 0.5f}));
        QVERIFY(std::abs(m.transmissionFactor - 0.75f) < 1e-6f);
        QVERIFY(near(m.emissiveFactor, {1.0f, 0.5f, 0.0f}));
        QCOMPARE(m.emissiveStrength, 2.0f);

        QVERIFY(hasWarning(r.warnings, "missing-texture"));
        QVERIFY(hasWarning(r.warnings, "texture-outside-folder"));
        const Image& missing = r.scene.images.at(r.scene.textures.at(m.baseColorTexture.texture).image);
        QVERIFY(missing.missing);
        QCOMPARE(missing.uri, std::string("missing.png"));
        const Image& refused = r.scene.images.at(r.scene.textures.at(m.specularColorTexture.texture).image);
        QVERIFY(refused.missing);
        QVERIFY(refused.encoded.empty());
    }

    void texturePathsAreConfinedToTheModelsFolder() {
        QTemporaryDir dir;
        const std::filesystem::path root = dir.path().toStdString();
        const std::filesystem::path folder = root / "model";
        std::filesystem::create_directory(folder);
        const std::string png = "\x89PNG\r\n\x1a\n";
        writeText(root / "secret.png", png);
        writeText(folder / "beside.png", png);
        std::filesystem::create_symlink(root / "secret.png", folder / "link.png");
        writeText(folder / "m.mtl", "newmtl a\nmap_Kd " + (root / "elsewhere" / "beside.png").string() + "\nmap_Ks link.png\n");
        writeText(folder / "m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n");

        LoadResult r = readWithAssimp(folder / "m.obj", {folder / "m.obj"});
        const Material& m = onlyMaterialOfFirstMesh(r.scene);
        // An absolute path is looked up by name beside the model.
        const Image& beside = r.scene.images.at(r.scene.textures.at(m.baseColorTexture.texture).image);
        QVERIFY(!beside.missing);
        QCOMPARE(beside.encoded.size(), png.size());
        QVERIFY(hasWarning(r.warnings, "texture-path-absolute"));
        // A symlink that leads out of the folder is refused.
        const Image& linked = r.scene.images.at(r.scene.textures.at(m.specularColorTexture.texture).image);
        QVERIFY(linked.missing);
        QVERIFY(linked.encoded.empty());
        QVERIFY(hasWarning(r.warnings, "texture-outside-folder"));
    }

    void embeddedTexturesKeepTheirBytes() {
        auto ai = meshScene({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
        static const unsigned char jpeg[] = {0xFF, 0xD8, 0xFF, 0xE0, 0x00, 0x10};
        auto* texture = new aiTexture;
        texture->mWidth = sizeof jpeg; // compressed: mHeight 0, mWidth bytes
        texture->mHeight = 0;
        texture->pcData = new aiTexel[2]; // aiTexture's destructor frees an aiTexel array
        std::memcpy(texture->pcData, jpeg, sizeof jpeg);
        ai->mNumTextures = 1;
        ai->mTextures = new aiTexture*[1]{texture};
        const aiString reference("*0");
        ai->mMaterials[0]->AddProperty(&reference, AI_MATKEY_TEXTURE_DIFFUSE(0));

        LoadResult r = convertAssimpScene(*ai, {"embedded.fbx"});
        const Material& m = onlyMaterialOfFirstMesh(r.scene);
        const Image& image = r.scene.images.at(r.scene.textures.at(m.baseColorTexture.texture).image);
        QCOMPARE(image.mimeType, std::string("image/jpeg"));
        QVERIFY(image.encoded == std::vector<std::uint8_t>(std::begin(jpeg), std::end(jpeg)));
        QVERIFY(image.uri.empty());
        QVERIFY(r.warnings.empty());
    }

    void roughnessFollowsTheBlinnPhongRelation() {
        QCOMPARE(roughnessFromShininess(0.0f), 1.0f);
        QVERIFY(std::abs(roughnessFromShininess(2.0f) - std::sqrt(0.5f)) < 1e-7f);
        QVERIFY(std::abs(roughnessFromShininess(198.0f) - 0.1f) < 1e-7f);
        QCOMPARE(roughnessFromShininess(-5.0f), 1.0f);
    }

    void plyKeepsVertexColoursAndTriangulatesTheQuad() {
        const auto file = kData / "import/quad.ply";
        LoadResult r = readWithAssimp(file, {file});
        QCOMPARE(totalTriangles(r.scene), std::size_t(2));
        const Primitive& p = r.scene.meshes.begin()->second.primitives.front();
        QCOMPARE(p.positions.size(), std::size_t(4));
        QCOMPARE(p.colors.size(), std::size_t(4));
        for (std::size_t i = 0; i < 4; ++i) {
            // The file's vertex i: (0,0,0) red, (1,0,0) green, (1,1,0) blue, (0,1,0) white.
            const glm::vec3 pos = p.positions[i];
            const glm::vec4 expected = pos == glm::vec3(0, 0, 0) ? glm::vec4(1, 0, 0, 1)
                                     : pos == glm::vec3(1, 0, 0) ? glm::vec4(0, 1, 0, 1)
                                     : pos == glm::vec3(1, 1, 0) ? glm::vec4(0, 0, 1, 1)
                                                                 : glm::vec4(1, 1, 1, 1);
            QCOMPARE(p.colors[i], expected);
        }
    }

    void stlIsKeptAsItIs() {
        const auto file = kData / "import/tetra.stl";
        LoadResult r = readWithAssimp(file, {file});
        QCOMPARE(totalTriangles(r.scene), std::size_t(4));
        const auto world = worldPositions(r.scene);
        QCOMPARE(world.size(), std::size_t(12)); // flat facets: no corner is shared
        for (glm::vec3 v : world) QVERIFY(v == glm::vec3(0, 0, 0) || v == glm::vec3(1, 0, 0) || v == glm::vec3(0, 1, 0) || v == glm::vec3(0, 0, 1));
        QVERIFY(std::count(world.begin(), world.end(), glm::vec3(0, 0, 1)) == 3); // +Z stays +Z
    }

    void colladaCentimetresAndZUpBecomeMetresAndYUp() {
        const auto file = kData / "import/triangle_zup_cm.dae";
        LoadResult r = readWithAssimp(file, {file});
        const auto world = worldPositions(r.scene);
        QCOMPARE(world.size(), std::size_t(3));
        // File: (0,0,0), (100,0,0), (0,0,200) cm with +Z up.
        QVERIFY(near(world[0], {0, 0, 0}));
        QVERIFY(near(world[1], {1, 0, 0}));
        QVERIFY(near(world[2], {0, 2, 0}));
        const Material& m = onlyMaterialOfFirstMesh(r.scene);
        QVERIFY(near(glm::vec3(m.baseColorFactor), {0.8f, 0.1f, 0.1f}));
        QVERIFY(std::abs(m.roughnessFactor - 0.2f) < 1e-6f); // shininess 48
        QVERIFY(std::abs(m.specularFactor - 0.5f) < 1e-6f);
    }

    void fbxMetadataUnitsAndAxesAreApplied() {
        auto ai = zUpCentimetreTriangle();
        LoadResult r = convertAssimpScene(*ai, {"triangle.fbx"});
        const auto world = worldPositions(r.scene);
        QCOMPARE(world.size(), std::size_t(3));
        QVERIFY(near(world[0], {0, 0, 0}));
        QVERIFY(near(world[1], {0, 0, -1})); // file +Y (front axis, sign -1) -> -Z, 100 cm -> 1 m
        QVERIFY(near(world[2], {0, 1, 0}));  // file +Z (up) -> +Y
    }

    void fbxFileInCentimetresZUpBecomesMetresYUp() {
        const auto file = kData / "import/tetra_zup_cm.fbx";
        LoadResult r = readWithAssimp(file, {file});
        QCOMPARE(totalTriangles(r.scene), std::size_t(4));
        const auto world = worldPositions(r.scene);
        QCOMPARE(world.size(), std::size_t(12));
        // File corners (1,0,0), (0,1,0), (0,0,1) in cm, +Z up and -Y front.
        auto count = [&](glm::vec3 p) { return std::count_if(world.begin(), world.end(), [&](glm::vec3 v) { return near(v, p); }); };
        QCOMPARE(count({0.01f, 0, 0}), 3);
        QCOMPARE(count({0, 0, -0.01f}), 3);
        QCOMPARE(count({0, 0.01f, 0}), 3);
        QCOMPARE(count({0, 0, 0}), 3);
    }

    void threeDsZUpBecomesYUp() {
        const auto file = kData / "import/tetra.3ds";
        LoadResult r = readWithAssimp(file, {file});
        QCOMPARE(totalTriangles(r.scene), std::size_t(4));
        const auto world = worldPositions(r.scene);
        auto count = [&](glm::vec3 p) { return std::count_if(world.begin(), world.end(), [&](glm::vec3 v) { return near(v, p); }); };
        QVERIFY(count({1, 0, 0}) > 0);
        QVERIFY(count({0, 0, -1}) > 0); // file +Y
        QVERIFY(count({0, 1, 0}) > 0);  // file +Z (up)
        QCOMPARE(count({0, 0, 1}), 0);
    }

    void pbrMaterialIsTakenAsItIs() {
        auto ai = zUpCentimetreTriangle();
        aiMaterial& m = *ai->mMaterials[0];
        const float metallic = 1.0f, roughness = 0.3f;
        const aiColor4D base(0.9f, 0.8f, 0.7f, 1.0f);
        m.AddProperty(&metallic, 1, AI_MATKEY_METALLIC_FACTOR);
        m.AddProperty(&roughness, 1, AI_MATKEY_ROUGHNESS_FACTOR);
        m.AddProperty(&base, 1, AI_MATKEY_BASE_COLOR);
        LoadResult r = convertAssimpScene(*ai, {"pbr.fbx"});
        const Material& out = onlyMaterialOfFirstMesh(r.scene);
        QCOMPARE(out.metallicFactor, 1.0f);
        QCOMPARE(out.roughnessFactor, 0.3f);
        QCOMPARE(out.baseColorFactor, glm::vec4(0.9f, 0.8f, 0.7f, 1.0f));
    }

    void triangleLimitIsEnforced() {
        auto ai = zUpCentimetreTriangle();
        ConvertOptions options{"limit.fbx"};
        options.maxTriangles = 0;
        try {
            convertAssimpScene(*ai, options);
            QFAIL("expected a FileError");
        } catch (const FileError& e) {
            QCOMPARE(e.code(), std::string("too-many-triangles"));
        }
    }

    void nonFiniteTrianglesAndNormalsAreRepaired() {
        const float nan = std::nanf("");
        auto ai = meshScene({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {nan, 0, 0}}, {{0, 1, 2}, {0, 1, 3}});
        aiMesh& mesh = *ai->mMeshes[0];
        mesh.mNormals = new aiVector3D[4]{{0, 0, 2}, {nan, 0, 0}, {0, 0, 0}, {0, 0, 1}};
        LoadResult r = convertAssimpScene(*ai, {"nan.obj"});
        const Primitive& p = r.scene.meshes.begin()->second.primitives.front();
        QCOMPARE(p.indices, (std::vector<std::uint32_t>{0, 1, 2}));
        QCOMPARE(p.normals[0], glm::vec3(0, 0, 1));
        QCOMPARE(p.normals[1], glm::vec3(0, 1, 0));
        QCOMPARE(p.normals[2], glm::vec3(0, 1, 0));
        QVERIFY(hasWarning(r.warnings, "non-finite-position"));
    }

    void cameraLooksWhereAssimpSaysWithTheVerticalFov() {
        auto ai = meshScene({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
        auto* camera = new aiCamera;
        camera->mPosition = aiVector3D(0, 1, 0);
        camera->mLookAt = aiVector3D(1, 0, 0); // along +X
        camera->mUp = aiVector3D(0, 1, 0);
        camera->mHorizontalFOV = 0.5f;        // half angle
        camera->mAspect = 2.0f;
        camera->mClipPlaneNear = 0.5f;
        camera->mClipPlaneFar = 200.0f;
        addRig(*ai, {camera}, {});
        LoadResult r = convertAssimpScene(*ai, {"rig.dae"});
        const Camera* c = nodeNamed(r.scene, "rig").get<Camera>();
        QVERIFY(c);
        QCOMPARE(c->projection, Projection::Perspective);
        QVERIFY(std::abs(c->yfov - 2.0f * std::atan(std::tan(0.5f) / 2.0f)) < 1e-6f);
        QCOMPARE(c->aspectRatio, 2.0f);
        QCOMPARE(c->znear, 0.5f);
        QCOMPARE(c->zfar, 200.0f);
        QVERIFY(near(worldAxis(r.scene, "rig", {0, 0, -1, 0}), {1, 0, 0}));
        QVERIFY(near(worldAxis(r.scene, "rig", {0, 1, 0, 0}), {0, 1, 0}));
        QVERIFY(near(glm::vec3(r.scene.worldFromNode(*r.scene.findByName("rig"))[3]), {0, 1, 5}));
        QVERIFY(!hasWarning(r.warnings, "cameras-dropped"));
    }

    void spotLightShinesAlongItsDirectionWithItsCone() {
        auto ai = meshScene({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
        auto* spot = new aiLight;
        spot->mType = aiLightSource_SPOT;
        spot->mDirection = aiVector3D(0, -1, 0);
        spot->mColorDiffuse = aiColor3D(20, 10, 5);
        spot->mAngleInnerCone = 0.2f;
        spot->mAngleOuterCone = 0.4f;
        addRig(*ai, {}, {spot});
        LoadResult r = convertAssimpScene(*ai, {"rig.fbx"});
        const Light* l = nodeNamed(r.scene, "rig").get<Light>();
        QVERIFY(l);
        QCOMPARE(l->type, LightType::Spot);
        QCOMPARE(l->intensity, 20.0f);
        QVERIFY(near(l->color, {1.0f, 0.5f, 0.25f}));
        QCOMPARE(l->innerConeAngle, 0.2f);
        QCOMPARE(l->outerConeAngle, 0.4f);
        QVERIFY(near(worldAxis(r.scene, "rig", {0, 0, -1, 0}), {0, -1, 0}));
        QVERIFY(hasWarning(r.warnings, "light-units-unknown"));
    }

    void cameraAndLightOnOneNodeBecomeChildren() {
        auto ai = meshScene({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
        auto* area = new aiLight;
        area->mType = aiLightSource_AREA;
        auto* point = new aiLight;
        point->mType = aiLightSource_POINT;
        point->mColorDiffuse = aiColor3D(1, 1, 1);
        addRig(*ai, {new aiCamera}, {point, area});
        LoadResult r = convertAssimpScene(*ai, {"rig.fbx"});
        QVERIFY(nodeNamed(r.scene, "rig.camera").get<Camera>());
        QVERIFY(nodeNamed(r.scene, "rig.light").get<Light>());
        QVERIFY(!nodeNamed(r.scene, "rig").get<Camera>());
        const auto dropped = std::find_if(r.warnings.begin(), r.warnings.end(), [](const Warning& w) { return w.code == "lights-dropped"; });
        QVERIFY(dropped != r.warnings.end());
        QCOMPARE(QString::fromStdString(dropped->message), QStringLiteral("1 lights dropped (area, ambient, or on no node)"));
    }

    void pointsOnlyIsNoGeometry() {
        auto ai = zUpCentimetreTriangle();
        ai->mMeshes[0]->mFaces[0].mNumIndices = 1; // a single point
        ai->mMeshes[0]->mPrimitiveTypes = aiPrimitiveType_POINT;
        try {
            convertAssimpScene(*ai, {"points.fbx"});
            QFAIL("expected a FileError");
        } catch (const FileError& e) {
            QCOMPARE(e.code(), std::string("no-geometry"));
            QCOMPARE(e.file(), std::string("points.fbx"));
        }
    }
};

QTEST_APPLESS_MAIN(TestImportConvert)
#include "test_import_convert.moc"
