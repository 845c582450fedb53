// glint's command line against docs/CLI.md: exit codes 0/1/2, "glint: FILE: problem" errors,
// --help with defaults, info/convert/render outputs.
#include "cli_runner.h"

#include "scene/io/scene_io.h"

#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

namespace {
const QString cornell = QStringLiteral(GLINT_RESOURCES_DIR "/scenes/cornell_box/cornell_box.gltf");
const QString bottle = QStringLiteral(GLINT_RESOURCES_DIR "/scenes/water_bottle/WaterBottle.gltf");

QByteArray readAll(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}
} // namespace

class TestCli : public QObject {
    Q_OBJECT
private slots:
    void versionAndHelp() {
        auto v = runGlint({"--version"});
        QCOMPARE(v.exitCode, 0);
        QVERIFY(v.out.startsWith("glint "));
        for (const char* cmd : {"info", "convert", "render", "encode"}) {
            auto h = runGlint({cmd, "--help"});
            QCOMPARE(h.exitCode, 0);
            QVERIFY2(h.out.contains("--help"), qPrintable(h.out));
        }
        auto h = runGlint({"render", "--help"});
        QVERIFY(h.out.contains("--size") && h.out.contains("--seed") && h.out.contains("default: 0"));
        for (const char* option : {"--animation", "--frames", "--fps", "--resume", "--shard", "--shards", "--video", "--aovs", "--time"})
            QVERIFY2(h.out.contains(option), option);
        auto e = runGlint({"encode", "--help"});
        QVERIFY(e.out.contains("--codec") && e.out.contains("--fps") && e.out.contains("default: from the container"));
    }

    void usageErrorsExitTwoWithOneLine() {
        for (const QStringList& args : {QStringList{"info"}, QStringList{"info", cornell, "--bogus"},
                                        QStringList{"render", cornell, "--out", "x.png", "--size", "12"},
                                        QStringList{"render", cornell, "--out", "x.png", "--config", "fancy"},
                                        QStringList{"convert", cornell, "out.obj"}, QStringList{"frobnicate"}}) {
            auto r = runGlint(args);
            QVERIFY2(r.exitCode == 2, qPrintable(args.join(' ') + " -> " + QString::number(r.exitCode)));
            QVERIFY2(r.err.startsWith("glint: ") && r.err.count('\n') == 1, qPrintable(r.err));
        }
    }

    // A mistyped subcommand never opens the editor on a file of that name (issue 17).
    void mistypedSubcommandExitsTwoWithTheNearestOne() {
        const QStringList display{"DISPLAY=:0", "QT_QPA_PLATFORM=offscreen"}; // the editor could open
        auto r = runGlint({"rendr", cornell, "--out", "x.png"}, display);
        QCOMPARE(r.exitCode, 2);
        QCOMPARE(r.err, QString("glint: unknown subcommand 'rendr' (did you mean render?)\n"));
        r = runGlint({"ifno", cornell}, display);
        QCOMPARE(r.err, QString("glint: unknown subcommand 'ifno' (did you mean info?)\n"));
        r = runGlint({"no/such/scene.gltf"}, display);
        QCOMPARE(r.exitCode, 2);
        QCOMPARE(r.err, QString("glint: no/such/scene.gltf: no such file, and not a subcommand (see --help)\n"));
    }

    void missingFileExitsOneNamingIt() {
        auto r = runGlint({"info", "no/such/scene.gltf"});
        QCOMPARE(r.exitCode, 1);
        QCOMPARE(r.err.trimmed(), QString("glint: no/such/scene.gltf: no such file"));
    }

    void infoJsonDescribesCornellBox() {
        auto r = runGlint({"info", cornell, "--json"});
        QCOMPARE(r.exitCode, 0);
        const auto j = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QCOMPARE(j["nodes"].toInt(), 9);
        QCOMPARE(j["meshes"].toArray().size(), 8);
        QCOMPARE(j["triangles"].toObject()["unique"].toInt(), 32); // 5 walls + light: 12; two open-bottomed blocks: 20
        QCOMPARE(j["triangles"].toObject()["instanced"].toInt(), 32);
        QCOMPARE(j["cameras"].toArray().size(), 1);
        QCOMPARE(j["cameras"].toArray()[0].toObject()["kind"].toString(), QString("perspective"));
        QCOMPARE(j["warnings"].toArray().size(), 0);
    }

    void strictTurnsWarningsIntoFailure() {
        QTemporaryDir dir;
        // A model whose texture is missing loads with a warning.
        QVERIFY(QFile::copy(GLINT_TEST_DATA_DIR "/gltf/TextureSettingsTest/TextureSettingsTest.gltf",
                            dir.filePath("t.gltf")));
        QVERIFY(QFile::copy(GLINT_TEST_DATA_DIR "/gltf/TextureSettingsTest/TextureSettingsTest0.bin",
                            dir.filePath("TextureSettingsTest0.bin")));
        auto lenient = runGlint({"info", dir.filePath("t.gltf")});
        QCOMPARE(lenient.exitCode, 0);
        QVERIFY2(lenient.err.contains("glint: warning: "), qPrintable(lenient.err));
        auto strict = runGlint({"info", dir.filePath("t.gltf"), "--strict"});
        QCOMPARE(strict.exitCode, 1);
    }

    void convertWritesValidDeterministicFiles() {
        QTemporaryDir dir;
        const QString a = dir.filePath("a.glb"), b = dir.filePath("b.glb");
        QCOMPARE(runGlint({"convert", cornell, a}).exitCode, 0);
        QCOMPARE(runGlint({"convert", a, b}).exitCode, 0);
        QVERIFY(!readAll(a).isEmpty());
        QCOMPARE(readAll(a), readAll(b)); // re-saving a file Glint wrote changes no byte
        auto r = runGlint({"info", b, "--json"});
        QCOMPARE(QJsonDocument::fromJson(r.out.toUtf8()).object()["triangles"].toObject()["unique"].toInt(), 32);
    }

    void convertImportsObj() {
        QTemporaryDir dir;
        auto r = runGlint({"convert", GLINT_TEST_DATA_DIR "/cornell/cornell_box.obj", dir.filePath("c.gltf")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(QFile::exists(dir.filePath("c.gltf")));
        QVERIFY(QFile::exists(dir.filePath("c.bin")) || !QDir(dir.path()).entryList({"*.bin"}).isEmpty());
    }

    void renderWritesPngAndExr() {
        QTemporaryDir dir;
        const QString png = dir.filePath("c.png"), exr = dir.filePath("c.exr");
        auto r = runGlint({"render", cornell, "--out", png, "--size", "32x24", "--spp", "2"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(r.err.contains("GL_RENDERER"));
        QImage image(png);
        QCOMPARE(image.size(), QSize(32, 24));
        auto e = runGlint({"render", cornell, "--out", exr, "--size", "32x24", "--spp", "2"});
        QVERIFY2(e.exitCode == 0, qPrintable(e.err));
        QVERIFY(readAll(exr).startsWith(QByteArray("\x76\x2f\x31\x01", 4))); // OpenEXR magic
        QVERIFY(QDir(dir.path()).entryList(QDir::Hidden | QDir::Files).filter("partial").isEmpty());
    }

    // A missing output folder is made, as the README's frames/shot_####.exr examples need.
    void renderCreatesTheOutputFolder() {
        QTemporaryDir dir;
        const QString still = dir.filePath("stills/day one/x.png");
        auto r = runGlint({"render", cornell, "--out", still, "--size", "8x8", "--spp", "1"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(QFileInfo(still).isFile());
        const QString converted = dir.filePath("converted/deep/scene.glb");
        r = runGlint({"convert", cornell, converted});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(QFileInfo(converted).isFile());
    }

    void renderSameSeedIsBitIdentical() {
        QTemporaryDir dir;
        const QString a = dir.filePath("a.png"), b = dir.filePath("b.png");
        QCOMPARE(runGlint({"render", cornell, "--out", a, "--size", "24x24", "--spp", "2", "--seed", "3"}).exitCode, 0);
        QCOMPARE(runGlint({"render", cornell, "--out", b, "--size", "24x24", "--spp", "2", "--seed", "3"}).exitCode, 0);
        QCOMPARE(readAll(a), readAll(b));
    }

    void renderToUnwritableFolderFails() {
        auto r = runGlint({"render", cornell, "--out", "/proc/no-such-dir/x.png", "--size", "8x8", "--spp", "1"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.startsWith("glint: /proc/no-such-dir/x.png: cannot create the output folder '/proc/no-such-dir'"),
                 qPrintable(r.err));
        // A file where the folder should be is named as such.
        QTemporaryDir dir;
        const QString file = dir.filePath("a-file");
        QFile plain(file);
        QVERIFY(plain.open(QIODevice::WriteOnly));
        plain.close();
        r = runGlint({"render", cornell, "--out", file + "/x.png", "--size", "8x8", "--spp", "1"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("'" + file + "' is a file, not a folder"), qPrintable(r.err));
    }

    // A display without an OpenGL 4.1 core context (here Qt's offscreen platform) used to crash the
    // editor at its first paint; it now opens without its viewport and says why.
    void editorWithoutOpenGlKeepsRunning() {
        QTemporaryDir home;
        QProcess editor;
        auto env = QProcessEnvironment::systemEnvironment();
        env.insert("QT_QPA_PLATFORM", "offscreen");
        env.remove("DISPLAY");
        env.remove("WAYLAND_DISPLAY");
        env.insert("XDG_CONFIG_HOME", home.filePath("config")); // no preferences or autosave of the user's
        env.insert("XDG_DATA_HOME", home.filePath("data"));
        editor.setProcessEnvironment(env);
        editor.start(QStringLiteral(GLINT_EXECUTABLE), {cornell});
        QVERIFY(editor.waitForStarted());
        QString err;
        QElapsedTimer clock;
        clock.start();
        while (!err.contains("without its viewport") && clock.elapsed() < 30000 && editor.state() == QProcess::Running) {
            editor.waitForReadyRead(200);
            err += QString::fromUtf8(editor.readAllStandardError());
        }
        QVERIFY2(err.contains("glint: This display gives no OpenGL 4.1 core context"), qPrintable(err));
        QTest::qWait(3000); // the window is shown and painted meanwhile
        QCOMPARE(editor.state(), QProcess::Running);
        editor.kill();
        editor.waitForFinished();
    }
};

QTEST_GUILESS_MAIN(TestCli)
#include "test_cli.moc"
