// A full disk and read-only folders during autosave, save and export (docs/RELIABILITY.md): each
// failure is a message naming the file and the problem, and what was there before stays whole: the
// previous autosave copy, the saved document, an image exported earlier. A full disk is a small
// tmpfs where the test may mount one (root), otherwise a file-size limit (writes fail with EFBIG
// instead of ENOSPC). Root ignores folder permissions, so a read-only folder is tried as nobody.
// The export plan (renderer headers, epoxy) before any Qt header.
#include "editor/export/export_plan.h"

#include "test_viewport_scene.h"

#include "editor/document/document.h"
#include "editor/export/export_job.h"
#include "editor/main_window/autosave.h"
#include "scene/history/camera_path_commands.h"
#include "scene/history/settings_commands.h"
#include "scene/io/scene_io.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <csignal>
#include <sys/fsuid.h>
#include <sys/resource.h>
#include <unistd.h>

using namespace glint;
using namespace glint::editor;

namespace {

constexpr uid_t kNobody = 65534;

QByteArray bytesOf(const QString& file) {
    QFile f(file);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

QStringList filesIn(const QString& folder) { return QDir(folder).entryList(QDir::Files | QDir::Hidden); }

// The calling thread checks file permissions as nobody while this lives (setfsuid drops root's
// file capabilities for this thread only): for what the GUI thread writes itself (autosave, save).
class NobodyOnThisThread {
public:
    NobodyOnThisThread() : root_(::geteuid() == 0) {
        if (!root_) return;
        ::setfsgid(kNobody);
        ::setfsuid(kNobody);
    }
    ~NobodyOnThisThread() {
        if (!root_) return;
        ::setfsuid(0);
        ::setfsgid(0);
    }
    NobodyOnThisThread(const NobodyOnThisThread&) = delete;
    NobodyOnThisThread& operator=(const NobodyOnThisThread&) = delete;

private:
    bool root_;
};

// The whole process (every thread: the export's worker) runs as nobody while this lives; root
// stays the saved user id, so it can come back.
class NobodyProcess {
public:
    NobodyProcess() : root_(::geteuid() == 0) {
        if (!root_) return;
        ok_ = ::setresgid(kNobody, kNobody, 0) == 0 && ::setresuid(kNobody, kNobody, 0) == 0;
    }
    ~NobodyProcess() {
        if (!root_) return;
        [[maybe_unused]] const int u = ::setresuid(0, 0, 0);
        [[maybe_unused]] const int g = ::setresgid(0, 0, 0);
    }
    bool ok() const { return ok_; }
    NobodyProcess(const NobodyProcess&) = delete;
    NobodyProcess& operator=(const NobodyProcess&) = delete;

private:
    bool root_;
    bool ok_ = true;
};

// A folder that is full: a small tmpfs filled up, or (without the right to mount) a file-size
// limit of the whole process below what the next write needs, for as long as this lives.
class FullFolder {
public:
    explicit FullFolder(const QString& folder, const QString& size = "1m") : folder_(folder) {
        QDir().mkpath(folder);
        mounted_ = QProcess::execute("mount", {"-t", "tmpfs", "-o", "size=" + size, "tmpfs", folder}) == 0;
    }
    ~FullFolder() {
        release();
        if (mounted_) QProcess::execute("umount", {folder_});
    }
    // From now on writes fail: the tmpfs filled up, or the size limit lowered to nothing.
    void fill() {
        if (mounted_) {
            QFile filler(folder_ + "/filler");
            if (!filler.open(QIODevice::WriteOnly)) return;
            const QByteArray block(4096, 'x');
            while (filler.write(block) == block.size() && filler.flush()) {}
            // Every page the filesystem has left: a smaller write after the last full block.
            while (filler.write("x", 1) == 1 && filler.flush()) {}
            return;
        }
        std::signal(SIGXFSZ, SIG_IGN);
        ::getrlimit(RLIMIT_FSIZE, &saved_);
        rlimit low = saved_;
        low.rlim_cur = 0;
        ::setrlimit(RLIMIT_FSIZE, &low);
        limited_ = true;
    }
    void release() {
        if (mounted_) QFile::remove(folder_ + "/filler");
        if (limited_) ::setrlimit(RLIMIT_FSIZE, &saved_);
        limited_ = false;
    }
    // The words the failing write gives: ENOSPC on the tmpfs, EFBIG under the limit.
    QString problem() const { return mounted_ ? "No space left on device" : "File too large"; }
    bool mounted() const { return mounted_; }

private:
    QString folder_;
    bool mounted_ = false;
    bool limited_ = false;
    rlimit saved_{};
};

void addSphere(Document& document, float x) { test::addShape(document, "Ball", ShapeKind::Sphere, {x, 0.0f, 0.0f}); }

QMap<QString, QByteArray> contentsOf(const QString& folder) {
    QMap<QString, QByteArray> contents;
    for (const QString& name : filesIn(folder)) contents.insert(name, bytesOf(folder + "/" + name));
    return contents;
}

// Points the document's environment image at `file` (an absolute path, as the editor stores an
// image chosen outside the scene's folder), as one undoable settings edit.
void chooseEnvironment(Document& document, const QString& file) {
    ProjectSettings settings = document.scene().settings;
    settings.environment.file = file.toStdString();
    document.push(std::make_unique<SetProjectSettings>(settings));
}

} // namespace

class TestSaveFailures : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        // nobody must reach the folders below.
        QVERIFY(QFile::setPermissions(dir_.path(), QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner |
                                                       QFileDevice::ReadGroup | QFileDevice::ExeGroup | QFileDevice::ReadOther |
                                                       QFileDevice::ExeOther));
    }

    void autosaveIntoAReadOnlyFolderKeepsThePreviousCopy() {
        const QString folder = dir_.filePath("autosave-read-only");
        Document document;
        Autosave autosave(document, folder);
        addSphere(document, 0.0f);
        QCOMPARE(autosave.saveNow(), QString());
        const QString copy = autosave.copyPath();
        const QByteArray before = bytesOf(copy);
        QVERIFY(!before.isEmpty());

        addSphere(document, 1.0f);
        QVERIFY(QFile::setPermissions(folder, QFileDevice::ReadOwner | QFileDevice::ExeOwner | QFileDevice::ReadOther | QFileDevice::ExeOther));
        QString error;
        {
            const NobodyOnThisThread nobody;
            error = autosave.saveNow();
        }
        QVERIFY(QFile::setPermissions(folder, QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner));
        QVERIFY2(error.contains(copy) && error.contains("Permission denied"), qPrintable(error));
        QCOMPARE(bytesOf(copy), before);
        QCOMPARE(loadScene(copy.toStdString()).scene.nodeCount(), std::size_t(1));
        QVERIFY(document.isModified()); // the work is still unsaved, and said so
    }

    void autosaveIntoAFullFolderKeepsThePreviousCopy() {
        const QString folder = dir_.filePath("autosave-full");
        FullFolder full(folder);
        Document document;
        Autosave autosave(document, folder);
        addSphere(document, 0.0f);
        QCOMPARE(autosave.saveNow(), QString());
        const QString copy = autosave.copyPath();
        const QByteArray before = bytesOf(copy);
        const QStringList filesBefore = filesIn(folder);

        addSphere(document, 1.0f);
        full.fill();
        const QString error = autosave.saveNow();
        full.release();
        QVERIFY2(error.contains(copy) && error.contains(full.problem()), qPrintable(error));
        QCOMPARE(bytesOf(copy), before);
        QCOMPARE(loadScene(copy.toStdString()).scene.nodeCount(), std::size_t(1));
        QCOMPARE(filesIn(folder), filesBefore); // no temporary left behind
        // Room again: the next autosave succeeds.
        QCOMPARE(autosave.saveNow(), QString());
        QCOMPARE(loadScene(copy.toStdString()).scene.nodeCount(), std::size_t(2));
    }

    void saveIntoAReadOnlyFolderKeepsTheFile() {
        const QString folder = dir_.filePath("save-read-only");
        QVERIFY(QDir().mkpath(folder));
        const QString file = folder + "/scene.gltf";
        Document document;
        addSphere(document, 0.0f);
        QCOMPARE(document.saveAs(file), QString());
        const QByteArray before = bytesOf(file);
        addSphere(document, 1.0f);
        QVERIFY(QFile::setPermissions(folder, QFileDevice::ReadOwner | QFileDevice::ExeOwner | QFileDevice::ReadOther | QFileDevice::ExeOther));
        QString error;
        {
            const NobodyOnThisThread nobody;
            error = document.save();
        }
        QVERIFY(QFile::setPermissions(folder, QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner));
        // The first file of the set it could not create is named (the buffer beside the scene).
        QVERIFY2(error.contains(folder + "/scene.") && error.contains("Permission denied"), qPrintable(error));
        QCOMPARE(bytesOf(file), before);
        QVERIFY(document.isModified());
        QCOMPARE(document.scene().nodeCount(), std::size_t(2));
    }

    // A save copies an environment image chosen outside the scene's folder beside the scene. Where
    // the copy does not fit, the whole save fails: the files saved before stay byte for byte, no
    // copy or temporary is left, and the document still reads the image from where it was.
    void saveCopyingTheEnvironmentIntoAFullFolderKeepsTheFiles() {
        const QString folder = dir_.filePath("save-environment-full");
        FullFolder full(folder, "4m"); // room for the 1.7 MB image once the filler is gone
        const QString file = folder + "/scene.gltf";
        Document document;
        addSphere(document, 0.0f);
        QCOMPARE(document.saveAs(file), QString());
        const QMap<QString, QByteArray> before = contentsOf(folder);
        QVERIFY(before.contains("scene.gltf") && before.size() >= 2); // the scene and its project file

        QVERIFY(QDir().mkpath(dir_.filePath("library")));
        const QString sky = dir_.filePath("library/sky.hdr");
        QVERIFY(QFile::copy(QStringLiteral(GLINT_RESOURCES_DIR "/env/studio_small_03_1k.hdr"), sky));
        chooseEnvironment(document, sky);
        full.fill();
        const QString error = document.save();
        full.release();
        QVERIFY2(error.contains(folder + "/") && error.contains(full.problem()), qPrintable(error));
        QCOMPARE(contentsOf(folder), before);
        QVERIFY(document.isModified());
        QCOMPARE(QString::fromStdString(document.scene().settings.environment.file), sky);

        // Room again: the image is copied and the document names the copy.
        QCOMPARE(document.save(), QString());
        QCOMPARE(bytesOf(folder + "/sky.hdr"), bytesOf(sky));
        QCOMPARE(document.scene().settings.environment.file, std::string("sky.hdr"));
        QCOMPARE(loadScene(file.toStdString()).scene.settings.environment.file, std::string("sky.hdr"));
        QVERIFY(!document.isModified());
    }

    void exportIntoAReadOnlyFolderSaysSoAndKeepsTheOldImage_data() {
        QTest::addColumn<bool>("animation");
        QTest::newRow("still") << false;
        QTest::newRow("animation") << true;
    }

    void exportIntoAReadOnlyFolderSaysSoAndKeepsTheOldImage() {
        QFETCH(bool, animation);
        const QString folder = dir_.filePath(animation ? "export-read-only-anim" : "export-read-only-still");
        QVERIFY(QDir().mkpath(folder));
        const QString old = folder + (animation ? "/shot_0000.png" : "/still.png");
        {
            QFile f(old);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("an image exported earlier");
        }
        QVERIFY(QFile::setPermissions(folder, QFileDevice::ReadOwner | QFileDevice::ExeOwner | QFileDevice::ReadOther | QFileDevice::ExeOther));
        const ExportSettings s = settingsFor(animation ? folder + "/shot_####.png" : old, animation);
        QString error;
        {
            const NobodyProcess nobody;
            QVERIFY(nobody.ok());
            error = runExport(s);
        }
        QVERIFY(QFile::setPermissions(folder, QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner));
        QVERIFY2(error.contains(old) && error.contains("is not writable: Permission denied"), qPrintable(error));
        QCOMPARE(bytesOf(old), QByteArray("an image exported earlier"));
        QCOMPARE(filesIn(folder), QStringList{QFileInfo(old).fileName()});
    }

    void exportIntoAFullFolderSaysSoAndKeepsTheOldImage_data() {
        QTest::addColumn<bool>("animation");
        QTest::newRow("still") << false;
        QTest::newRow("animation") << true;
    }

    void exportIntoAFullFolderSaysSoAndKeepsTheOldImage() {
        QFETCH(bool, animation);
        const QString folder = dir_.filePath(animation ? "export-full-anim" : "export-full-still");
        FullFolder full(folder);
        const QString old = folder + (animation ? "/shot_0000.png" : "/still.png");
        {
            QFile f(old);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("an image exported earlier");
        }
        const QStringList filesBefore = filesIn(folder);
        const ExportSettings s = settingsFor(animation ? folder + "/shot_####.png" : old, animation);
        full.fill();
        const QString error = runExport(s);
        full.release();
        QVERIFY2(error.contains(old) && error.contains(full.problem()), qPrintable(error));
        QCOMPARE(bytesOf(old), QByteArray("an image exported earlier"));
        QCOMPARE(filesIn(folder), filesBefore); // no partial file, no later frame
    }

private:
    ExportSettings settingsFor(const QString& out, bool animation) {
        if (!sceneReady_) {
            test::buildShapesScene(scene_);
            Node camera;
            camera.name = "cam";
            camera.local.translation = {0.0f, 0.3f, 4.0f};
            camera.component = Camera{};
            scene_.push(std::make_unique<AddNode>(std::move(camera)));
            // A camera path over 2 frames at 24 fps: frames 0, 1, 2.
            const NodeId cam = *scene_.scene().findByName("cam");
            CameraKey a;
            a.position = {0.0, 0.3, 4.0};
            CameraKey b = a;
            b.time = 2.0 / 24.0;
            b.position = {0.5, 0.3, 4.0};
            scene_.push(std::make_unique<AddCameraKey>(cam, a));
            scene_.push(std::make_unique<AddCameraKey>(cam, b));
            sceneReady_ = true;
        }
        ExportSettings s;
        s.out = out.toStdString();
        s.width = 48;
        s.height = 32;
        s.spp = 1;
        s.configuration = "accumulate";
        s.animation = animation;
        s.firstFrame = 0;
        s.lastFrame = animation ? 2 : 0;
        return s;
    }

    QString runExport(const ExportSettings& s) {
        ExportController controller;
        QSignalSpy finished(&controller, &ExportController::finished);
        try {
            controller.start(scene_.scene(), s);
        } catch (const std::exception& e) {
            return QString::fromUtf8(e.what());
        }
        if (!finished.wait(60000)) return "the export did not finish";
        return finished.first().at(0).toString();
    }

    QTemporaryDir dir_;
    Document scene_;
    bool sceneReady_ = false;
};

QTEST_MAIN(TestSaveFailures)
#include "test_save_failures.moc"
