// The files around a scene: GLB containers, external buffers and images, the folder check
// (no `..`, no absolute paths, no symlinks out), missing and oversized images.
#include "io_read_helpers.h"

#include "scene/io/project/project_file.h"

#include <QTemporaryDir>
#include <QTest>

#include <filesystem>

using namespace glint;
using namespace glint::test;
namespace fs = std::filesystem;

namespace {

// The triangle with its buffer in `name` beside the .gltf.
Json withExternalBuffer(const fs::path& folder, const std::string& name)
{
    const GltfBuilder b = triangle();
    writeFile(folder / name, b.bin);
    Json doc = b.finish();
    doc["buffers"][0]["uri"] = name;
    return doc;
}

Json withImage(Json doc, const std::string& uri)
{
    doc["images"] = Json::array({{{"uri", uri}}});
    doc["textures"] = Json::array({{{"source", 0}}});
    doc["materials"] = Json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}});
    doc["meshes"][0]["primitives"][0]["material"] = 0;
    return doc;
}

std::vector<std::uint8_t> validGlb()
{
    const GltfBuilder b = triangle();
    Json doc = b.finish();
    doc["buffers"][0].erase("uri");
    return makeGlb(doc, b.bin);
}

void setU32(std::vector<std::uint8_t>& bytes, std::size_t at, std::uint32_t v)
{
    for (int i = 0; i < 4; ++i) bytes[at + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(v >> (8 * i));
}

} // namespace

class TestGltfReadFiles : public QObject {
    Q_OBJECT

private:
    QTemporaryDir dir_;
    fs::path folder() const { return fs::path(dir_.path().toStdString()); }

private slots:
    void glbLoads()
    {
        const LoadResult r = loadGltfFromMemory(validGlb(), folder(), "t.glb");
        QCOMPARE(r.scene.meshes.begin()->second.primitives[0].positions[1], glm::vec3(1, 0, 0));
    }

    void truncatedGlb()
    {
        std::vector<std::uint8_t> glb = validGlb();
        glb.resize(glb.size() / 2);
        GLINT_EXPECT_ERROR(loadGltfFromMemory(glb, folder(), "t.glb"), "truncated-glb", "the GLB header declares");
        glb.resize(9);
        GLINT_EXPECT_ERROR(loadGltfFromMemory(glb, folder(), "t.glb"), "truncated-glb", "the GLB header is cut short (9 of 12 bytes)");
    }

    void glbChunkLengthPastTheEnd()
    {
        std::vector<std::uint8_t> glb = validGlb();
        setU32(glb, 12, 0x7FFFFFF0);
        GLINT_EXPECT_ERROR(loadGltfFromMemory(glb, folder(), "t.glb"), "glb-chunk-out-of-range", "JSON chunk claims 2147483632 bytes");
        glb = validGlb();
        const std::size_t binHeader = 20 + (glb[12] | glb[13] << 8);
        setU32(glb, binHeader, 4096);
        GLINT_EXPECT_ERROR(loadGltfFromMemory(glb, folder(), "t.glb"), "glb-chunk-out-of-range", "BIN chunk claims 4096 bytes");
    }

    void glbBinShorterThanDeclared()
    {
        const GltfBuilder b = triangle();
        Json doc = b.finish();
        doc["buffers"][0].erase("uri");
        doc["buffers"][0]["byteLength"] = 400;
        GLINT_EXPECT_ERROR(loadGltfFromMemory(makeGlb(doc, b.bin), folder(), "t.glb"), "buffer-too-short", "declares 400 bytes, but its data holds only 44");
    }

    void externalBufferLoads()
    {
        const LoadResult r = loadJson(withExternalBuffer(folder(), "ok.bin"), folder());
        QCOMPARE(r.scene.meshes.begin()->second.primitives[0].indices, (std::vector<std::uint32_t>{0, 1, 2}));
    }

    void missingBin()
    {
        Json doc = withExternalBuffer(folder(), "present.bin");
        doc["buffers"][0]["uri"] = "absent.bin";
        GLINT_EXPECT_ERROR(loadJson(doc, folder()), "missing-file", "buffers[0] names 'absent.bin'");
    }

    void externalBufferShorterThanDeclared()
    {
        Json doc = withExternalBuffer(folder(), "short.bin");
        doc["buffers"][0]["byteLength"] = 100;
        GLINT_EXPECT_ERROR(loadJson(doc, folder()), "buffer-too-short", "declares 100 bytes, but its data holds only 44");
    }

    void uriEscapingTheFolder_data()
    {
        QTest::addColumn<QString>("uri");
        QTest::addColumn<QString>("message");
        QTest::newRow("dot dot") << "../../x.bin" << "leads out of the scene's folder";
        QTest::newRow("dot dot inside") << "sub/../../x.bin" << "leads out of the scene's folder";
        QTest::newRow("absolute") << "/etc/passwd" << "is an absolute path";
        QTest::newRow("percent-encoded dot dot") << "%2E%2E/x.bin" << "leads out of the scene's folder";
    }

    void uriEscapingTheFolder()
    {
        QFETCH(QString, uri);
        QFETCH(QString, message);
        Json doc = withExternalBuffer(folder(), "b.bin");
        doc["buffers"][0]["uri"] = uri.toStdString();
        GLINT_EXPECT_ERROR(loadJson(doc, folder()), "uri-escapes-folder", message.toStdString());
        GLINT_EXPECT_ERROR(loadJson(withImage(withExternalBuffer(folder(), "b.bin"), uri.toStdString()), folder()), "uri-escapes-folder", message.toStdString());
    }

    void symlinkOutOfTheFolder()
    {
        QTemporaryDir outside;
        const fs::path secret = fs::path(outside.path().toStdString()) / "secret.bin";
        writeFile(secret, triangle().bin);
        fs::create_directory(folder() / "scene");
        fs::create_symlink(secret, folder() / "scene" / "link.bin");
        Json doc = withExternalBuffer(folder() / "scene", "b.bin");
        doc["buffers"][0]["uri"] = "link.bin";
        GLINT_EXPECT_ERROR(loadJson(doc, folder() / "scene"), "uri-escapes-folder", "'link.bin' resolves through a symlink to a place outside the scene's folder: refused");
    }

    // The project file's environment image follows the glTF URI rule (docs/FILE_FORMAT.md): refused at load,
    // naming the project file and the key.
    void environmentEscapingTheFolder_data()
    {
        QTest::addColumn<QString>("env");
        QTest::addColumn<QString>("message");
        QTest::newRow("dot dot") << "../outside.hdr" << "key 'environment.file': '../outside.hdr' leads out of the scene's folder ('..'): refused";
        QTest::newRow("dot dot inside") << "hdr/../../outside.hdr" << "leads out of the scene's folder";
        QTest::newRow("absolute") << "/etc/passwd" << "key 'environment.file': '/etc/passwd' is an absolute path";
        QTest::newRow("symlink out") << "link.hdr" << "key 'environment.file': 'link.hdr' resolves through a symlink to a place outside the scene's folder: refused";
    }

    void environmentEscapingTheFolder()
    {
        QFETCH(QString, env);
        QFETCH(QString, message);
        const fs::path scene = folder() / "envscene";
        fs::create_directories(scene);
        writeFile(folder() / "outside.hdr", {1, 2, 3});
        if (!fs::is_symlink(scene / "link.hdr")) fs::create_symlink(folder() / "outside.hdr", scene / "link.hdr");
        writeFile(scene / "s.gltf", bytesOf(triangle().finish().dump()));
        const fs::path project = scene / "s.glint.json";
        writeFile(project, bytesOf(Json{{"glint", 1}, {"scene", "s.gltf"}, {"environment", {{"file", env.toStdString()}}}}.dump()));
        for (const fs::path& file : {scene / "s.gltf", project}) {
            const Caught caught = errorOf([&] { (void)loadScene(file); });
            QCOMPARE(QString::fromStdString(caught.code), QStringLiteral("uri-escapes-folder"));
            QCOMPARE(QString::fromStdString(caught.file), QString::fromStdString(project.string()));
            QVERIFY2(caught.message.find(message.toStdString()) != std::string::npos, caught.message.c_str());
        }
        // The renderer's check before it opens the image is the same rule.
        const Caught again = errorOf([&] { (void)projectEnvironmentPath(scene, env.toStdString(), scene.string()); });
        QCOMPARE(QString::fromStdString(again.code), QStringLiteral("uri-escapes-folder"));
    }

    void environmentInsideTheFolderLoads()
    {
        const fs::path scene = folder() / "envinside";
        fs::create_directories(scene / "hdr");
        writeFile(scene / "hdr" / "studio.hdr", {1, 2, 3});
        fs::create_symlink("studio.hdr", scene / "hdr" / "alias.hdr");
        writeFile(scene / "s.gltf", bytesOf(triangle().finish().dump()));
        for (const char* env : {"hdr/studio.hdr", "hdr/alias.hdr", "./hdr/../hdr/studio.hdr"}) {
            writeFile(scene / "s.glint.json", bytesOf(Json{{"glint", 1}, {"environment", {{"file", env}}}}.dump()));
            QCOMPARE(QString::fromStdString(loadScene(scene / "s.gltf").scene.settings.environment.file), QString(env));
        }
    }

    // activeCamera must name a camera node of the glTF it belongs to.
    void danglingActiveCameraIsRefused()
    {
        const fs::path scene = folder() / "activecamera";
        fs::create_directories(scene);
        writeFile(scene / "s.gltf", bytesOf(triangle().finish().dump()));
        writeFile(scene / "s.glint.json", bytesOf(Json{{"glint", 1}, {"activeCamera", 12345}}.dump()));
        const Caught caught = errorOf([&] { (void)loadScene(scene / "s.gltf"); });
        QCOMPARE(QString::fromStdString(caught.code), QStringLiteral("bad-value"));
        QCOMPARE(QString::fromStdString(caught.file), QString::fromStdString((scene / "s.glint.json").string()));
        QCOMPARE(QString::fromStdString(caught.message),
                 QStringLiteral("key 'activeCamera' must be the id of a camera node of the scene: 12345 names no node"));
        writeFile(scene / "s.glint.json", bytesOf(Json{{"glint", 1}, {"activeCamera", 1}}.dump()));
        GLINT_EXPECT_ERROR(loadScene(scene / "s.gltf"), "bad-value", "1 is not a camera");
    }

    void symlinkInsideTheFolderIsFine()
    {
        fs::create_directory(folder() / "inner");
        Json doc = withExternalBuffer(folder() / "inner", "real.bin");
        fs::create_symlink("real.bin", folder() / "inner" / "alias.bin");
        doc["buffers"][0]["uri"] = "alias.bin";
        QCOMPARE(loadJson(doc, folder() / "inner").scene.nodeCount(), std::size_t(1));
    }

    void missingTextureIsAPlaceholder()
    {
        const LoadResult r = loadJson(withImage(withExternalBuffer(folder(), "m.bin"), "gone.png"), folder());
        const Image& image = r.scene.images.begin()->second;
        QVERIFY(image.missing);
        QCOMPARE(QString::fromStdString(image.uri), QStringLiteral("gone.png"));
        const Warning* w = findWarning(r.warnings, "missing-texture");
        QVERIFY(w && w->message.find("'gone.png'") != std::string::npos);
    }

    void undecodableTextureIsAPlaceholder()
    {
        writeFile(folder() / "noise.png", {1, 2, 3, 4, 5, 6, 7, 8});
        const LoadResult r = loadJson(withImage(withExternalBuffer(folder(), "n.bin"), "noise.png"), folder());
        QVERIFY(r.scene.images.begin()->second.missing);
        QCOMPARE(r.scene.images.begin()->second.encoded.size(), std::size_t(8)); // kept, never re-encoded
        QVERIFY(findWarning(r.warnings, "missing-texture")->message.find("cannot be decoded") != std::string::npos);
    }

    void imageHeaderClaimingHugeSizeIsRefused()
    {
        writeFile(folder() / "huge.png", pngHeader(65535, 65535));
        GLINT_EXPECT_ERROR(loadJson(withImage(withExternalBuffer(folder(), "h.bin"), "huge.png"), folder()), "image-too-large",
                           "image 0 claims 65535x65535 pixels, more than the limit of 268435456");
    }

    void imageKeepsOriginalBytesAndSize()
    {
        const std::vector<std::uint8_t> header = pngHeader(32, 16);
        writeFile(folder() / "small.png", header);
        const LoadResult r = loadJson(withImage(withExternalBuffer(folder(), "s.bin"), "small.png"), folder());
        const Image& image = r.scene.images.begin()->second;
        QCOMPARE(image.encoded, header);
        QCOMPARE(image.width, 32);
        QCOMPARE(image.height, 16);
        QCOMPARE(QString::fromStdString(image.mimeType), QStringLiteral("image/png"));
        QVERIFY(!image.missing);
    }

    void embeddedImageStaysEmbedded()
    {
        const std::vector<std::uint8_t> header = pngHeader(8, 4);
        const LoadResult r = loadJson(withImage(triangle().finish(), "data:image/png;base64," + base64(header)), folder());
        const Image& image = r.scene.images.begin()->second;
        QVERIFY(image.uri.empty());
        QCOMPARE(image.encoded, header);
        QCOMPARE(QString::fromStdString(image.mimeType), QStringLiteral("image/png"));
    }

    void malformedImageDataUri()
    {
        GLINT_EXPECT_ERROR(loadJson(withImage(triangle().finish(), "data:image/png;base64,@@@@"), folder()), "malformed-data-uri", "images[0].uri");
    }

    void projectFileBesideTheSceneIsRead()
    {
        fs::create_directory(folder() / "project");
        const GltfBuilder b = triangle();
        Json doc = b.finish();
        doc["buffers"][0].erase("uri");
        doc["cameras"] = Json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}}});
        doc["nodes"].push_back({{"camera", 0}});
        doc["scenes"][0]["nodes"].push_back(1);
        writeFile(folder() / "project" / "shot.glb", makeGlb(doc, b.bin));
        ProjectFile project;
        project.sceneFile = "shot.glb";
        project.settings.render.spp = 7;
        project.settings.activeCamera = NodeId{2}; // the camera node (ids 1..N in glTF node order)
        writeFile(folder() / "project" / "shot.glint.json", bytesOf(writeProjectFileText(project)));
        const LoadResult viaScene = loadScene(folder() / "project" / "shot.glb");
        QCOMPARE(viaScene.scene.settings.render.spp, 7);
        const LoadResult viaProject = loadScene(folder() / "project" / "shot.glint.json");
        QCOMPARE(viaProject.scene.settings.activeCamera, NodeId{2});
        QCOMPARE(viaProject.scene.nodeCount(), std::size_t(2));
        LoadOptions withoutProject;
        withoutProject.loadProjectFile = false;
        QCOMPARE(loadScene(folder() / "project" / "shot.glb", withoutProject).scene.settings.render.spp, ProjectSettings{}.render.spp);
    }

    void projectFileNamingASceneOutsideItsFolder()
    {
        ProjectFile project;
        project.sceneFile = "../elsewhere.glb";
        writeFile(folder() / "escape.glint.json", bytesOf(writeProjectFileText(project)));
        GLINT_EXPECT_ERROR(loadScene(folder() / "escape.glint.json"), "uri-escapes-folder", "'../elsewhere.glb' leads out of the scene's folder");
    }

    void loadSceneDispatchesOnExtension()
    {
        writeFile(folder() / "scene.glb", validGlb());
        QCOMPARE(loadScene(folder() / "scene.glb").scene.nodeCount(), std::size_t(1));
        GLINT_EXPECT_ERROR(loadScene(folder() / "scene.obj"), "unsupported-format", "can only load .gltf, .glb or .glint.json");
        GLINT_EXPECT_ERROR(loadScene(folder() / "nothing.gltf"), "missing-file", "cannot read the file");
    }
};

QTEST_APPLESS_MAIN(TestGltfReadFiles)
#include "test_gltf_read_files.moc"
