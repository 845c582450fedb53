// Render passes at the command line (docs/CLI.md, "Render passes"): the project's output block
// (path, aovs, passes, codec) drives `glint render SCENE` with no options, the command line's
// options override it, and a bad pass name, in the project or in --passes, is a usage error that
// names it. Tiny images: what is checked here is which file, which channels and which codec.
#include "cli_runner.h"
#include "image_probe.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>

namespace {

const QString kDolly = QStringLiteral(GLINT_RESOURCES_DIR "/farm/cornell_dolly.gltf"); // 1 s camera path
const QStringList kTiny = {"--size", "16x16", "--spp", "1"};

void writeText(const QString& file, const QByteArray& text) {
    QFile f(file);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(text);
}

// dir/name/s.gltf (the Cornell box along a camera path) with `project` as its project file.
QString sceneWithProject(const QTemporaryDir& dir, const QString& name, const QByteArray& project) {
    QDir(dir.path()).mkpath(name);
    const QString folder = dir.filePath(name);
    QFile::copy(kDolly, folder + "/s.gltf");
    writeText(folder + "/s.glint.json", project);
    return folder + "/s.gltf";
}

QString videoCodec(const QString& file) {
    QProcess p;
    p.start("ffprobe", {"-v", "error", "-select_streams", "v:0", "-show_entries", "stream=codec_name", "-of", "json", file});
    p.waitForFinished(60000);
    const auto streams = QJsonDocument::fromJson(p.readAllStandardOutput()).object()["streams"].toArray();
    return streams.isEmpty() ? QString() : streams[0].toObject()["codec_name"].toString();
}

} // namespace

class TestCliPasses : public QObject {
    Q_OBJECT

private slots:
    // output.path, output.aovs and output.passes make the still; --passes and --aovs override them.
    void theProjectsOutputBlockDrivesRender() {
        QTemporaryDir dir;
        const QString scene = sceneWithProject(
            dir, "block", R"({"glint": 1, "output": {"path": "out/still.exr", "aovs": "depth", "passes": "emit,ENV,Vector"}})");
        const CliResult r = runGlint(QStringList{"render", scene, "--time", "0.5"} + kTiny);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const ProbedImage still = probeImage(dir.filePath("block/out/still.exr"));
        QVERIFY(still.ok);
        QCOMPARE(sorted(still.channels), sorted({"R", "G", "B", "A", "Z", "Emit.R", "Emit.G", "Emit.B", "Env.R", "Env.G",
                                                 "Env.B", "Vector.X", "Vector.Y"}));
        QCOMPARE(glintAttr(still, "passes"), QString("Emit,Env,Vector"));
        QVERIFY(std::abs(glintAttr(still, "vectorSeconds").toDouble() - 1.0 / 24.0) < 1e-12); // one frame at the default 24 fps
        // The dolly moves the camera: somewhere the vectors are not 0.
        const auto x = std::find(still.channels.begin(), still.channels.end(), "Vector.X") - still.channels.begin();
        float largest = 0.0f;
        for (std::size_t i = std::size_t(x); i < still.pixels.size(); i += still.channels.size())
            largest = std::max(largest, std::abs(still.pixels[i]));
        QVERIFY2(largest > 0.01f, qPrintable(QString::number(largest)));

        const QString other = dir.filePath("other.exr");
        const CliResult overridden = runGlint(QStringList{"render", scene, "--out", other, "--passes", "DiffDir",
                                                          "--aovs", "none"} + kTiny);
        QVERIFY2(overridden.exitCode == 0, qPrintable(overridden.err));
        const ProbedImage image = probeImage(other);
        QCOMPARE(sorted(image.channels), sorted({"R", "G", "B", "A", "DiffDir.R", "DiffDir.G", "DiffDir.B"}));
        QCOMPARE(glintAttr(image, "passes"), QString("DiffDir"));
        // --passes none: no passes, and no "passes" entry (earlier frames keep their settings hash).
        const CliResult none = runGlint(QStringList{"render", scene, "--out", other, "--passes", "none"} + kTiny);
        QCOMPARE(none.exitCode, 0);
        QVERIFY(glintAttr(probeImage(other), "passes").isEmpty());
    }

    // An animation from output.path's pattern, its video encoded with output.codec (FFV1 in a
    // .mov, whose own default would be ProRes).
    void theProjectsCodecEncodesTheVideo() {
        QTemporaryDir dir;
        const QString scene = sceneWithProject(
            dir, "video", R"({"glint": 1, "output": {"path": "f/s_##.exr", "passes": "light", "codec": "ffv1"}})");
        const QString video = dir.filePath("video/v.mov");
        const CliResult r = runGlint(QStringList{"render", scene, "--frames", "0-1", "--video", video} + kTiny);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const ProbedImage frame = probeImage(dir.filePath("video/f/s_01.exr"));
        QVERIFY(frame.ok);
        QCOMPARE(glintAttr(frame, "passes"), QString("DiffDir,DiffInd,GlossDir,GlossInd,Emit,Env"));
        QCOMPARE(videoCodec(video), QString("ffv1"));
    }

    // Usage errors (exit 2), one line naming the pass and where it was asked for.
    void aBadPassNameIsNamed() {
        QTemporaryDir dir;
        const QString scene = sceneWithProject(dir, "bad", R"({"glint": 1, "output": {"path": "x.exr", "passes": "DiffDir,Shadow"}})");
        const CliResult fromProject = runGlint(QStringList{"render", scene} + kTiny);
        QCOMPARE(fromProject.exitCode, 2);
        QCOMPARE(fromProject.err.trimmed(),
                 "glint: " + dir.filePath("bad/s.glint.json") +
                     ": key 'output.passes': unknown render pass 'Shadow' (use all, none, light or a list of DiffDir, "
                     "DiffInd, GlossDir, GlossInd, Emit, Env, Vector)");
        QVERIFY(!QFile::exists(dir.filePath("bad/x.exr")));
        // --passes wins over the project's (so a good one makes the bad one harmless).
        QCOMPARE(runGlint(QStringList{"render", scene, "--passes", "Emit"} + kTiny).exitCode, 0);

        const CliResult fromOption = runGlint(QStringList{"render", scene, "--out", dir.filePath("y.exr"), "--passes", "emit,glosdir"} + kTiny);
        QCOMPARE(fromOption.exitCode, 2);
        QVERIFY2(fromOption.err.contains("unknown render pass 'glosdir'"), qPrintable(fromOption.err));
        QCOMPARE(fromOption.err.trimmed().count('\n'), 0);

        const CliResult realTime = runGlint(QStringList{"render", scene, "--out", dir.filePath("z.exr"), "--passes", "all",
                                                        "--config", "full"} + kTiny);
        QCOMPARE(realTime.exitCode, 2);
        QCOMPARE(realTime.err.trimmed(), QString("glint: --passes: render passes need the accumulate or reference configuration, not 'full'"));
    }
};

QTEST_GUILESS_MAIN(TestCliPasses)
#include "test_cli_passes.moc"
