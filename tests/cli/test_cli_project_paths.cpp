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

    // The project's output block stands in for --out: its path, relative to the scene's folder,
    // receives the still (folders made as for --out); a path out of the folder is refused naming
    // the key, and with neither the command says what is missing. All usage errors: exit 2.
    void projectOutputPathStandsInForOut() {
        QTemporaryDir dir;
        const QString scene = sceneWithProject(dir, "out", R"({"glint": 1, "output": {"path": "renders/still.png"}})");
        CliResult r = runGlint({"render", scene, "--size", "8x8", "--spp", "1"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(QFile::exists(dir.filePath("out/renders/still.png")));

        const QString escaping = sceneWithProject(dir, "escape-out", R"({"glint": 1, "output": {"path": "../stolen.png"}})");
        r = runGlint({"render", escaping, "--size", "8x8", "--spp", "1"});
        QCOMPARE(r.exitCode, 2);
        QCOMPARE(r.err.trimmed(), "glint: " + dir.filePath("escape-out/s.glint.json") +
                                      ": key 'output.path': '../stolen.png' leads out of the scene's folder ('..'): refused");
        QVERIFY(!QFile::exists(dir.filePath("stolen.png")));

        const QString none = sceneWithProject(dir, "none", R"({"glint": 1})");
        r = runGlint({"render", none, "--size", "8x8", "--spp", "1"});
        QCOMPARE(r.exitCode, 2);
        QCOMPARE(r.err.trimmed(), "glint: --out is required: " + dir.filePath("none/s.glint.json") + " sets no output.path");
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
