// Atomic saving: a child process saves two different scenes alternately over one file set while the
// parent SIGKILLs it at random moments (fixed seeds); after every kill the folder must hold the
// complete previous or new set, byte for byte. Failures leave no temporaries behind.
#include "feature_scene.h"
#include "io_write_helpers.h"

#include "scene/io/files/atomic_save.h"
#include "scene/io/project/project_file.h"
#include "scene/io/scene_io.h"

#include <QTemporaryDir>
#include <QtTest>

#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <random>
#include <thread>

using namespace glint;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

// The exact files one variant's save produces, keyed by name relative to the folder.
using FileSet = std::map<std::string, std::vector<std::uint8_t>>;

FileSet filesOf(const fs::path& folder)
{
    FileSet set;
    for (const std::string& name : test::listFiles(folder)) set[name] = test::readBytes(folder / name);
    return set;
}

bool sameFile(const fs::path& file, const FileSet& reference, const std::string& name)
{
    auto it = reference.find(name);
    return it != reference.end() && fs::exists(file) && test::readBytes(file) == it->second;
}

// Empty when the loader opens the set (the byte checks above already prove it complete).
std::string loaderProblem(const fs::path& gltf)
{
    try {
        loadScene(gltf);
    } catch (const FileError& e) {
        return std::string("the loader refuses it: ") + e.what();
    }
    return {};
}

// Empty when the folder holds a complete set: the glTF of one variant, every buffer and image it
// names with that variant's bytes, and a project file of either variant (a kill between the glTF
// and the project file leaves the previous project file, as documented in atomic_save.h).
std::string incompleteSet(const fs::path& folder, const std::vector<FileSet>& variants)
{
    const fs::path gltf = folder / "scene.gltf";
    for (const FileSet& variant : variants) {
        if (!sameFile(gltf, variant, "scene.gltf")) continue;
        const json j = json::parse(test::readText(gltf));
        for (const json& buffer : j["buffers"]) {
            const std::string uri = buffer["uri"];
            if (!sameFile(folder / uri, variant, uri)) return "buffer " + uri + " is missing or differs";
            if (fs::file_size(folder / uri) != buffer["byteLength"].get<std::uintmax_t>()) return "buffer " + uri + " has the wrong size";
        }
        for (const json& image : j["images"])
            if (image.contains("uri") && !sameFile(folder / image["uri"].get<std::string>(), variant, image["uri"]))
                return "image " + image["uri"].get<std::string>() + " is missing or differs";
        bool projectComplete = false;
        for (const FileSet& any : variants) projectComplete = projectComplete || sameFile(folder / "scene.glint.json", any, "scene.glint.json");
        if (!projectComplete) return "the project file is missing or torn";
        return loaderProblem(gltf);
    }
    return "scene.gltf is missing or matches neither variant";
}

FileSet referenceSet(const Scene& scene)
{
    QTemporaryDir dir;
    saveScene(scene, fs::path(dir.path().toStdString()) / "scene.gltf");
    return filesOf(dir.path().toStdString());
}

[[noreturn]] void saveForever(const std::vector<Scene>& scenes, const fs::path& file)
{
    for (std::size_t i = 0;; ++i) {
        try {
            saveScene(scenes[i % scenes.size()], file);
        } catch (...) {
            _exit(3);
        }
    }
}

bool hasTemporaries(const fs::path& folder)
{
    const auto files = test::listFiles(folder);
    return std::any_of(files.begin(), files.end(), [](const std::string& f) { return isTemporaryName(f); });
}

// Runs `body` as another user when this process is root (root ignores folder permissions).
int runUnprivileged(const std::function<int()>& body)
{
    if (::geteuid() != 0) return body();
    const pid_t child = ::fork();
    if (child == 0) {
        if (::setgid(65534) != 0 || ::setuid(65534) != 0) _exit(90);
        _exit(body());
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 99;
}

} // namespace

class TestAtomicSave : public QObject {
    Q_OBJECT

private slots:
    void killedSavesLeaveACompleteSet()
    {
        const std::vector<Scene> scenes{test::largeScene(200, 0), test::largeScene(200, 1)};
        const std::vector<FileSet> variants{referenceSet(scenes[0]), referenceSet(scenes[1])};
        QVERIFY(variants[0].at("scene.gltf") != variants[1].at("scene.gltf"));

        QTemporaryDir dir;
        const fs::path folder = dir.path().toStdString();
        const auto start = std::chrono::steady_clock::now();
        saveScene(scenes[0], folder / "scene.gltf");
        const auto oneSave = std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - start);

        constexpr int kKills = 60;
        std::map<std::string, int> outcomes;
        for (int round = 0; round < kKills; ++round) {
            std::mt19937 random(static_cast<std::uint32_t>(round));
            const auto delay = std::chrono::microseconds(std::uniform_int_distribution<std::int64_t>(0, 3 * oneSave.count())(random));
            const pid_t child = ::fork();
            QVERIFY(child >= 0);
            if (child == 0) saveForever(scenes, folder / "scene.gltf");
            std::this_thread::sleep_for(delay);
            ::kill(child, SIGKILL);
            int status = 0;
            ::waitpid(child, &status, 0);
            QVERIFY2(WIFSIGNALED(status), "the saving child ended on its own (a save failed)");
            const std::string problem = incompleteSet(folder, variants);
            QVERIFY2(problem.empty(), ("after kill " + std::to_string(round) + ": " + problem).c_str());
            ++outcomes[test::readBytes(folder / "scene.gltf") == variants[0].at("scene.gltf") ? "A" : "B"];
            outcomes[hasTemporaries(folder) ? "temporaries left" : "clean"]++;
        }
        qInfo("one save: %lld us; after %d kills: A %d, B %d, with temporaries %d", static_cast<long long>(oneSave.count()),
              kKills, outcomes["A"], outcomes["B"], outcomes["temporaries left"]);

        // A save that finishes clears what the killed ones left: exactly the reference set remains.
        saveScene(scenes[1], folder / "scene.gltf");
        QVERIFY(filesOf(folder) == variants[1]);
    }

    // A save killed between its glTF's rename and its project file's leaves the new project file
    // whole under its temporary name: loading reads it (with a warning), as it belongs to the glTF
    // on disk. Not when the glTF's own temporary is still there (its save did not get that far), nor
    // when the temporary is older than the glTF (another program saved the glTF since).
    void projectFileOfAnInterruptedSaveIsRead()
    {
        QTemporaryDir dir;
        const fs::path folder = dir.path().toStdString();
        Scene scene = test::largeScene(10, 0);
        scene.settings.render.spp = 16;
        saveScene(scene, folder / "scene.gltf");
        ProjectSettings newer = scene.settings;
        newer.render.spp = 99;
        const fs::path temporary = folder / ".scene.glint.json.glint-tmp0";
        std::ofstream(temporary, std::ios::binary) << writeProjectFileText({"scene.gltf", newer});
        LoadResult loaded = loadScene(folder / "scene.gltf");
        QCOMPARE(loaded.scene.settings.render.spp, 99);
        QVERIFY(std::any_of(loaded.warnings.begin(), loaded.warnings.end(),
                            [](const Warning& w) { return w.code == "project-save-interrupted"; }));

        fs::last_write_time(temporary, fs::last_write_time(folder / "scene.gltf") - std::chrono::seconds(10));
        QCOMPARE(loadScene(folder / "scene.gltf").scene.settings.render.spp, 16);
        fs::last_write_time(temporary, fs::last_write_time(folder / "scene.gltf") + std::chrono::seconds(1));
        std::ofstream(folder / ".scene.gltf.glint-tmp1", std::ios::binary) << "{";
        QCOMPARE(loadScene(folder / "scene.gltf").scene.settings.render.spp, 16);

        // The next save puts its own project file in place and clears the temporaries.
        saveScene(scene, folder / "scene.gltf");
        QVERIFY(!hasTemporaries(folder));
        QCOMPARE(loadScene(folder / "scene.gltf").scene.settings.render.spp, 16);
    }

    void readOnlyFolderThrowsAndLeavesNothing()
    {
        QTemporaryDir dir;
        const fs::path folder = fs::path(dir.path().toStdString()) / "read-only";
        fs::create_directory(folder);
        QCOMPARE(::chmod(dir.path().toLocal8Bit().constData(), 0755), 0);
        QCOMPARE(::chmod(folder.c_str(), 0555), 0);
        const Scene scene = test::featureScene();
        const int result = runUnprivileged([&] {
            try {
                saveScene(scene, folder / "scene.gltf");
            } catch (const FileError& e) {
                const bool named = e.code() == "write-failed" && e.message().find("Permission denied") != std::string::npos;
                return named ? 0 : 1;
            }
            return 2;
        });
        QCOMPARE(result, 0);
        QVERIFY(test::listFiles(folder).empty());
    }

    void failurePartWayRemovesTemporariesAndKeepsTheOldSet()
    {
        QTemporaryDir dir;
        const fs::path folder = dir.path().toStdString();
        Scene scene = test::featureScene();
        scene.images.at(ImageId{1}).uri = "blocked/checker.png";
        scene.images.at(ImageId{1}).encoded = test::checkerPng();
        saveScene(test::featureScene(), folder / "scene.gltf");
        const FileSet before = filesOf(folder);
        std::ofstream(folder / "blocked") << "a file where the image folder would go";
        try {
            saveScene(scene, folder / "scene.gltf");
            QFAIL("the save must fail: its image folder cannot be created");
        } catch (const FileError& e) {
            QCOMPARE(e.code(), std::string("write-failed"));
            QCOMPARE(e.file(), (folder / "blocked/checker.png").string());
        }
        fs::remove(folder / "blocked");
        QVERIFY(!hasTemporaries(folder));
        QVERIFY(filesOf(folder) == before);
    }

    void temporaryNamesNeverMatchFinalOnes()
    {
        QVERIFY(isTemporaryName(".scene.gltf.glint-tmp0"));
        QVERIFY(isTemporaryName("textures/.checker.png.glint-tmp12"));
        QVERIFY(!isTemporaryName("scene.gltf"));
        QVERIFY(!isTemporaryName(".scene.gltf.glint-tmp"));
        QVERIFY(!isTemporaryName("scene.glint-tmp0"));
    }
};

QTEST_APPLESS_MAIN(TestAtomicSave)
#include "test_atomic_save.moc"
