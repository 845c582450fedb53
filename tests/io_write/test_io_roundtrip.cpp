// Round trips of real files: every sample model and the bundled scenes load, save (.gltf and
// .glb), load again into an equal Scene; a second save is byte-identical (also under de_DE), and
// every saved file passes the Khronos validator with 0 errors (not in sanitizer builds, which
// have no validator installed).
#include "feature_scene.h"
#include "io_write_helpers.h"
#ifdef GLINT_VALIDATE_OUTPUT
#include "validator_run.h"
#endif

#include "scene/io/scene_io.h"

#include <QTemporaryDir>
#include <QtTest>

#include <chrono>
#include <clocale>

using namespace glint;
namespace fs = std::filesystem;

namespace {

std::vector<fs::path> sampleModels()
{
    std::vector<fs::path> models;
    for (const auto& entry : fs::recursive_directory_iterator(fs::path(GLINT_TEST_DATA_DIR) / "gltf")) {
        const std::string ext = entry.path().extension().string();
        if (entry.is_regular_file() && (ext == ".gltf" || ext == ".glb")) models.push_back(entry.path());
    }
    models.push_back(fs::path(GLINT_RESOURCES_DIR) / "scenes/cornell_box/cornell_box.gltf");
    models.push_back(fs::path(GLINT_RESOURCES_DIR) / "scenes/water_bottle/WaterBottle.gltf");
    std::sort(models.begin(), models.end());
    return models;
}

std::map<std::string, std::vector<std::uint8_t>> filesOf(const fs::path& folder)
{
    std::map<std::string, std::vector<std::uint8_t>> set;
    for (const std::string& name : test::listFiles(folder)) set[name] = test::readBytes(folder / name);
    return set;
}

std::string firstDifference(const fs::path& a, const fs::path& b)
{
    const auto left = filesOf(a);
    const auto right = filesOf(b);
    for (const auto& [name, bytes] : left) {
        auto it = right.find(name);
        if (it == right.end()) return name + " is missing from the second save";
        if (it->second != bytes) return name + " differs";
    }
    return left.size() == right.size() ? "" : "the second save has other files";
}

// A .gltf saved as .glb embeds its images: the only change a conversion may make is that image
// URIs become empty (the bytes stay the same).
bool sameButEmbedded(const Scene& glb, Scene source)
{
    for (auto& [id, image] : source.images) image.uri.clear();
    return glb == source;
}

// Restores the C locale however the test ends.
struct LocaleGuard {
    ~LocaleGuard() { std::setlocale(LC_ALL, "C"); }
};

} // namespace

class TestIoRoundTrip : public QObject {
    Q_OBJECT

private slots:
    void sampleModel_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("format");
        for (const fs::path& model : sampleModels())
            for (const char* format : {".gltf", ".glb"})
                QTest::newRow((model.filename().string() + " as " + format).c_str())
                    << QString::fromStdString(model.string()) << QString(format);
    }

    void sampleModel()
    {
        QFETCH(QString, file);
        QFETCH(QString, format);
        const LoadResult original = loadScene(file.toStdString());
        QTemporaryDir first, second;
        const fs::path savedFile = fs::path(first.path().toStdString()) / ("saved" + format.toStdString());
        saveScene(original.scene, savedFile);

        const LoadResult reloaded = loadScene(savedFile);
        QVERIFY2(reloaded.scene == original.scene || sameButEmbedded(reloaded.scene, original.scene),
                 "load -> save -> load changed the scene");

        saveScene(reloaded.scene, fs::path(second.path().toStdString()) / ("saved" + format.toStdString()));
        const std::string difference = firstDifference(first.path().toStdString(), second.path().toStdString());
        QVERIFY2(difference.empty(), difference.c_str());

#ifdef GLINT_VALIDATE_OUTPUT
        const std::string errors = test::validatorErrors({savedFile});
        QVERIFY2(errors.empty(), errors.c_str());
#endif
    }

    void resaveUnderGermanLocaleIsIdentical()
    {
        const LoadResult bottle = loadScene(fs::path(GLINT_RESOURCES_DIR) / "scenes/water_bottle/WaterBottle.gltf");
        QTemporaryDir c, german;
        saveScene(bottle.scene, fs::path(c.path().toStdString()) / "bottle.gltf");
        {
            LocaleGuard guard;
            QVERIFY2(std::setlocale(LC_ALL, "de_DE.UTF-8") != nullptr,
                     "the locale de_DE.UTF-8 is missing: generate it (localedef -i de_DE -f UTF-8 de_DE.UTF-8)");
            const LoadResult again = loadScene(fs::path(c.path().toStdString()) / "bottle.gltf");
            saveScene(again.scene, fs::path(german.path().toStdString()) / "bottle.gltf");
        }
        const std::string difference = firstDifference(c.path().toStdString(), german.path().toStdString());
        QVERIFY2(difference.empty(), difference.c_str());
    }

    void featureSceneSurvivesTheLoader()
    {
        QTemporaryDir first, second;
        const fs::path saved = fs::path(first.path().toStdString()) / "features.gltf";
        saveScene(test::featureScene(), saved);
        const LoadResult loaded = loadScene(saved);
        Scene expected = test::featureScene();
        expected.unsupported.clear();
        QVERIFY2(loaded.scene.settings == expected.settings, "project settings differ after loading");
        QVERIFY2(loaded.scene.nodes() == expected.nodes(), "nodes differ after loading");
        QVERIFY2(loaded.scene.materials == expected.materials, "materials differ after loading");
        QVERIFY2(loaded.scene.meshes == expected.meshes, "meshes differ after loading");
        QVERIFY2(loaded.scene.images == expected.images, "images differ after loading");
        QVERIFY2(loaded.scene.textures == expected.textures, "textures differ after loading");
        QVERIFY2(loaded.scene.samplers == expected.samplers, "samplers differ after loading");
        QVERIFY2(loaded.scene.animations == expected.animations, "animations differ after loading");
        QVERIFY2(loaded.scene == expected, "the scene differs after loading");
        saveScene(loaded.scene, fs::path(second.path().toStdString()) / "features.gltf");
        const std::string difference = firstDifference(first.path().toStdString(), second.path().toStdString());
        QVERIFY2(difference.empty(), difference.c_str());
    }

    // The KHR_materials_specular, _transmission and _volume textures with their own texCoord,
    // KHR_texture_transform and unknown textureInfo extensions: kept through load, written back
    // byte-identically, validator-clean, in both formats.
    void extensionTexturesRoundTrip_data()
    {
        QTest::addColumn<QString>("format");
        QTest::newRow("gltf") << QString(".gltf");
        QTest::newRow("glb") << QString(".glb");
    }

    void extensionTexturesRoundTrip()
    {
        QFETCH(QString, format);
        Scene scene = test::featureScene();
        scene.unsupported.clear();
        for (auto& [id, m] : scene.materials) {
            if (!m.specularTexture.valid()) continue;
            m.specularTexture.texCoord = 1;
            m.specularColorTexture.transform = {.offset = {0.25f, 0.5f}, .rotation = 0.3f, .scale = {2.0f, 0.5f}, .texCoord = 1};
            m.transmissionTexture.transform = {.offset = {0.0f, 0.125f}};
            m.transmissionTexture.unknown = {{"extensions", {{"EXT_glint_test_info", {{"k", 1}}}}}};
            m.thicknessTexture.texCoord = 1;
            m.thicknessTexture.transform = {.scale = {3.0f, 3.0f}};
        }
        QTemporaryDir first, second;
        const fs::path saved = fs::path(first.path().toStdString()) / ("ext" + format.toStdString());
        saveScene(scene, saved);
        const LoadResult loaded = loadScene(saved);
        QVERIFY2(loaded.scene.materials == scene.materials, "materials differ after loading");
        for (const Warning& w : loaded.warnings) QVERIFY2(w.code != "extension-dropped", w.message.c_str());
        saveScene(loaded.scene, fs::path(second.path().toStdString()) / ("ext" + format.toStdString()));
        const std::string difference = firstDifference(first.path().toStdString(), second.path().toStdString());
        QVERIFY2(difference.empty(), difference.c_str());
#ifdef GLINT_VALIDATE_OUTPUT
        const std::string errors = test::validatorErrors({saved});
        QVERIFY2(errors.empty(), errors.c_str());
#endif
    }

    void saveTimeOfTheLargestModel()
    {
        const LoadResult engine = loadScene(fs::path(GLINT_TEST_DATA_DIR) / "gltf/2CylinderEngine/2CylinderEngine.glb");
        QTemporaryDir dir;
        for (const char* format : {".glb", ".gltf"}) {
            const auto start = std::chrono::steady_clock::now();
            saveScene(engine.scene, fs::path(dir.path().toStdString()) / (std::string("engine") + format));
            const auto ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            qInfo("2CylinderEngine saved as %s in %.1f ms", format, ms);
        }
        const auto start = std::chrono::steady_clock::now();
        const auto bytes = writeGlb(engine.scene);
        const auto ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        qInfo("2CylinderEngine writeGlb in memory: %zu bytes in %.1f ms", bytes.size(), ms);
        QVERIFY(bytes.size() > 1000000);
    }
};

QTEST_APPLESS_MAIN(TestIoRoundTrip)
#include "test_io_roundtrip.moc"
