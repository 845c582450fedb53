// The project file at the command line: an environment path that leaves the scene's folder and
// render values out of range are refused at load naming the file and the key; `glint convert` into
// another folder takes the environment image along, so the copy renders, with the same bytes twice.
#include "cli_runner.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

namespace {

const QString kCornell = QStringLiteral(GLINT_RESOURCES_DIR "/scenes/cornell_box/cornell_box.gltf");
const QString kEnv = QStringLiteral(GLINT_TEST_DATA_DIR "/env/studio_small_03_1k.hdr");

QByteArray readAll(const QString& file) {
    QFile f(file);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

void writeText(const QString& file, const QByteArray& text) {
    QFile f(file);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(text);
}

// dir/name/s.gltf (the Cornell box, which has a camera) with `project` as its project file.
QString sceneWithProject(const QTemporaryDir& dir, const QString& name, const QByteArray& project) {
    QDir(dir.path()).mkpath(name + "/hdr");
    const QString folder = dir.filePath(name);
    QFile::copy(kCornell, folder + "/s.gltf");
    QFile::copy(kEnv, folder + "/hdr/studio.hdr");
    writeText(folder + "/s.glint.json", project);
    return folder + "/s.gltf";
}

} // namespace

class TestCliProjectPaths : public QObject {
    Q_OBJECT

private slots:
    void environmentOutsideTheFolderIsRefused() {
        QTemporaryDir dir;
        // Absolute paths and symlinks out are refused by the same check (tests/io_read); one process here.
        const QString scene = sceneWithProject(dir, "escape", R"({"glint": 1, "environment": {"file": "../../etc/passwd"}})");
        const CliResult r = runGlint({"info", scene});
        QCOMPARE(r.exitCode, 1);
        QCOMPARE(r.err.trimmed(), "glint: " + dir.filePath("escape/s.glint.json") +
                                      ": key 'environment.file': '../../etc/passwd' leads out of the scene's folder ('..'): refused");
    }

    void renderValueOutOfRangeIsRefusedAtLoad() {
        QTemporaryDir dir;
        const QString scene = sceneWithProject(dir, "range", R"({"glint": 1, "render": {"width": 0, "height": 0}})");
        const CliResult r = runGlint({"info", scene});
        QCOMPARE(r.exitCode, 1);
        QCOMPARE(r.err.trimmed(), "glint: " + dir.filePath("range/s.glint.json") + ": key 'render.width' must be an integer from 1 to 16384");
    }

    void convertTakesTheEnvironmentAlong() {
        QTemporaryDir dir;
        const QString scene = sceneWithProject(dir, "a", R"({"glint": 1, "environment": {"file": "hdr/studio.hdr"}})");
        const QString first = dir.filePath("b/x.gltf"), second = dir.filePath("c/x.gltf");
        const CliResult convert = runGlint({"convert", scene, first});
        QCOMPARE(convert.exitCode, 0);
        QVERIFY2(convert.err.isEmpty(), qPrintable(convert.err));
        QCOMPARE(runGlint({"convert", scene, second}).exitCode, 0);
        QVERIFY(readAll(dir.filePath("b/hdr/studio.hdr")) == readAll(kEnv));
        for (const char* name : {"x.gltf", "x.glint.json", "hdr/studio.hdr"})
            QVERIFY2(readAll(dir.filePath(QString("b/") + name)) == readAll(dir.filePath(QString("c/") + name)), name);
        // The converted scene renders with its environment (before the fix: "cannot read the environment image").
        const CliResult render = runGlint({"render", first, "--size", "8x8", "--spp", "1", "--out", dir.filePath("b.exr")});
        QVERIFY2(render.exitCode == 0, qPrintable(render.err));
        QVERIFY(QFile::exists(dir.filePath("b.exr")));
    }
};

QTEST_GUILESS_MAIN(TestCliProjectPaths)
#include "test_cli_project_paths.moc"
