// The project's environment image on save: copied beside a scene saved into another folder (same
// relative path, same bytes), nothing copied in place, an image from outside the folder brought in,
// and what cannot be kept named in the report. Saving twice gives the same bytes.
#include "feature_scene.h"

#include "scene/io/project/project_file.h"
#include "scene/io/scene_io.h"

#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <variant>

using namespace glint;
namespace fs = std::filesystem;

namespace {

std::vector<std::uint8_t> readBytes(const fs::path& file)
{
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeBytes(const fs::path& file, const std::vector<std::uint8_t>& bytes)
{
    fs::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

// Stands in for a Radiance HDR: the save copies bytes, it never decodes them.
std::vector<std::uint8_t> hdrBytes()
{
    std::vector<std::uint8_t> bytes(4096);
    for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = std::uint8_t(i * 7 + 3);
    return bytes;
}

const Warning* findCode(const Warnings& warnings, const std::string& code)
{
    auto it = std::find_if(warnings.begin(), warnings.end(), [&](const Warning& w) { return w.code == code; });
    return it == warnings.end() ? nullptr : &*it;
}

// Every regular file under `folder`, relative path -> bytes.
std::map<std::string, std::vector<std::uint8_t>> filesUnder(const fs::path& folder)
{
    std::map<std::string, std::vector<std::uint8_t>> files;
    for (const auto& entry : fs::recursive_directory_iterator(folder))
        if (entry.is_regular_file()) files[entry.path().lexically_relative(folder).generic_string()] = readBytes(entry.path());
    return files;
}

} // namespace

class TestEnvironmentSave : public QObject {
    Q_OBJECT

private:
    QTemporaryDir dir_;
    fs::path root() const { return fs::path(dir_.path().toStdString()); }

    // A scene saved in a/ with its environment image in a/hdr/, loaded back from there.
    LoadResult sourceScene(const std::string& name)
    {
        const fs::path a = root() / name;
        Scene scene = test::featureScene();
        scene.settings.environment.file = "hdr/studio.hdr";
        writeBytes(a / "hdr" / "studio.hdr", hdrBytes());
        saveScene(scene, a / "s.gltf");
        return loadScene(a / "s.gltf");
    }

private slots:
    void saveIntoAnotherFolderCopiesTheEnvironment()
    {
        const LoadResult loaded = sourceScene("copy");
        SaveOptions options;
        options.sourceFolder = root() / "copy";
        const fs::path b = root() / "copy-out";
        const SaveReport report = saveScene(loaded.scene, b / "x.gltf", options);
        QVERIFY(!findCode(report.dropped, "environment-not-copied") && !findCode(report.dropped, "environment-dropped"));
        QVERIFY(readBytes(b / "hdr" / "studio.hdr") == hdrBytes());
        const LoadResult converted = loadScene(b / "x.gltf");
        QCOMPARE(QString::fromStdString(converted.scene.settings.environment.file), QStringLiteral("hdr/studio.hdr"));
        QVERIFY(std::find(report.written.begin(), report.written.end(), b / "hdr" / "studio.hdr") != report.written.end());

        // Twice, and from the converted copy again: the same bytes in every file.
        const fs::path c = root() / "copy-again";
        saveScene(loaded.scene, c / "x.gltf", options);
        QVERIFY(filesUnder(b) == filesUnder(c));
        SaveOptions fromB;
        fromB.sourceFolder = b;
        const fs::path d = root() / "copy-of-copy";
        saveScene(converted.scene, d / "x.gltf", fromB);
        QVERIFY(filesUnder(b) == filesUnder(d));
    }

    void saveInPlaceCopiesNothing()
    {
        const LoadResult loaded = sourceScene("inplace");
        const fs::path a = root() / "inplace";
        const SaveReport report = saveScene(loaded.scene, a / "s.gltf");
        QVERIFY(report.dropped.empty() || !findCode(report.dropped, "environment-not-copied"));
        QVERIFY(std::find(report.written.begin(), report.written.end(), a / "hdr" / "studio.hdr") == report.written.end());
        QVERIFY(readBytes(a / "hdr" / "studio.hdr") == hdrBytes());
    }

    // An image that cannot be read cannot come along: the path is kept, the report says so.
    void unreadableEnvironmentIsNamed()
    {
        const LoadResult loaded = sourceScene("unnamed");
        fs::remove(root() / "unnamed" / "hdr" / "studio.hdr");
        SaveOptions options;
        options.sourceFolder = root() / "unnamed";
        const fs::path b = root() / "unnamed-out";
        const SaveReport report = saveScene(loaded.scene, b / "x.gltf", options);
        const Warning* w = findCode(report.dropped, "environment-not-copied");
        QVERIFY(w);
        QCOMPARE(QString::fromStdString(w->file), QString::fromStdString((b / "x.gltf").string()));
        QVERIFY2(w->message.find("environment image 'hdr/studio.hdr'") != std::string::npos, w->message.c_str());
        QVERIFY(!fs::exists(b / "hdr"));
    }

    // An HDR picked outside the folder (the editor stores it relative, with '..') is brought into
    // the folder under its own name, so the saved project opens again.
    void environmentFromOutsideIsBroughtIn()
    {
        const fs::path a = root() / "outside" / "scene";
        writeBytes(root() / "outside" / "library" / "sky.hdr", hdrBytes());
        Scene scene = test::featureScene();
        scene.settings.environment.file = "../library/sky.hdr";
        SaveOptions options;
        options.sourceFolder = a;
        const SaveReport report = saveScene(scene, a / "s.gltf", options);
        const Warning* dropped = findCode(report.dropped, "environment-dropped");
        QVERIFY2(!dropped, dropped ? dropped->message.c_str() : "");
        QVERIFY(readBytes(a / "sky.hdr") == hdrBytes());
        QCOMPARE(QString::fromStdString(loadScene(a / "s.gltf").scene.settings.environment.file), QStringLiteral("sky.hdr"));

        scene.settings.environment.file = "../library/gone.hdr";
        const SaveReport gone = saveScene(scene, a / "s.gltf", options);
        QVERIFY(findCode(gone.dropped, "environment-dropped"));
        QVERIFY(loadScene(a / "s.gltf").scene.settings.environment.file.empty());
    }

    void danglingActiveCameraIsLeftOut()
    {
        Scene scene = test::featureScene();
        scene.settings.activeCamera = NodeId{12345};
        const fs::path a = root() / "camera";
        const SaveReport report = saveScene(scene, a / "s.gltf");
        const Warning* w = findCode(report.dropped, "active-camera-dropped");
        QVERIFY(w);
        QVERIFY2(w->message.find("12345") != std::string::npos, w->message.c_str());
        QVERIFY(!loadScene(a / "s.gltf").scene.settings.activeCamera.valid());
    }
};

QTEST_APPLESS_MAIN(TestEnvironmentSave)
#include "test_environment_save.moc"
