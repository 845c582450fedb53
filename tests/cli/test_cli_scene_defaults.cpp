// Scenes that cannot render as stored: most downloaded glTF assets have no camera and no light.
// `glint render` frames a camera-less scene from a default view and says so, says when nothing
// lights the scene, names the file when --camera names no camera, and --strict refuses the
// fallback. The Khronos Box sample (no camera, no light), 32x32 px, 1 spp, llvmpipe.
#include "cli_runner.h"
#include "image_probe.h"

#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>

namespace {

const QString kBox = QStringLiteral(GLINT_TEST_DATA_DIR "/gltf/Box/Box.gltf");
const QString kEnv = QStringLiteral(GLINT_TEST_DATA_DIR "/env/studio_small_03_1k.hdr");

QString warning(const QString& text) { return QStringLiteral("glint: warning: %1: %2").arg(kBox, text); }

const QString kNoCamera = warning("the scene has no camera: rendering from a default view of the whole scene "
                                  "(\"Default view\") [no-camera]");
const QString kNoLight = warning("nothing in the scene emits light (no light, emissive material or environment): "
                                 "the image will be black; add a light or pass --env FILE [no-light]");

float idAt(const ProbedImage& image, int x, int y) {
    const auto channel = std::find(image.channels.begin(), image.channels.end(), "id") - image.channels.begin();
    return image.pixels[(std::size_t(y) * image.width + x) * image.channels.size() + channel];
}

} // namespace

class TestCliSceneDefaults : public QObject {
    Q_OBJECT
private slots:
    void cameralessSceneIsFramedByTheDefaultView() {
        QTemporaryDir dir;
        const QString out = dir.filePath("box.exr");
        const CliResult r = runGlint({"render", kBox, "--env", kEnv, "--size", "32x32", "--spp", "1", "--out", out});
        qInfo("stderr:\n%s", qPrintable(r.err));
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(r.err.count(kNoCamera), 1);
        QCOMPARE(r.err.count("[no-light]"), 0); // --env lights it
        const ProbedImage image = probeImage(out);
        QVERIFY(image.ok);
        // The box fills the middle and the sphere around it fits inside: the corners see the sky.
        QVERIFY(idAt(image, 16, 16) > 0.0f);
        for (const auto& [x, y] : {std::pair{0, 0}, {31, 0}, {0, 31}, {31, 31}}) QCOMPARE(idAt(image, x, y), 0.0f);
    }

    void unlitSceneIsNamedAndStillRenders() {
        QTemporaryDir dir;
        const CliResult r = runGlint({"render", kBox, "--size", "32x32", "--spp", "1", "--out", dir.filePath("box.png")});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(r.err.count(kNoLight), 1);
        QVERIFY(QFile::exists(dir.filePath("box.png")));
    }

    // A triangle whose only light is an emissive texture (a white 1x1 PNG, factor 1, glTF's default
    // strength), as on a bottle's label or a helmet's lamps: the image is mostly dark, and the
    // warning says why; --env lights it.
    void sceneLitOnlyByEmissiveTexturesIsNamed() {
        QTemporaryDir dir;
        const QString file = QStringLiteral(GLINT_TEST_DATA_DIR "/gltf/EmissiveLabel/EmissiveLabel.gltf");
        const QString expected = QStringLiteral("glint: warning: %1: only emissive textures give light (no light, untextured emissive "
                                                "material or environment): most of the image will be dark; add a light or pass --env "
                                                "FILE [only-emissive-textures]")
                                     .arg(file);
        const CliResult r = runGlint({"render", file, "--size", "32x32", "--spp", "1", "--out", dir.filePath("glow.png")});
        qInfo("stderr:\n%s", qPrintable(r.err));
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(r.err.count(expected), 1);
        QCOMPARE(r.err.count("[no-light]"), 0);
        const CliResult lit = runGlint({"render", file, "--env", kEnv, "--size", "32x32", "--spp", "1", "--out", dir.filePath("lit.png")});
        QCOMPARE(lit.exitCode, 0);
        QCOMPARE(lit.err.count("[only-emissive-textures]"), 0);
    }

    void unknownCameraNamesTheFile() {
        QTemporaryDir dir;
        const CliResult r = runGlint({"render", kBox, "--camera", "nope", "--size", "32x32", "--spp", "1", "--out",
                                      dir.filePath("box.png")});
        QCOMPARE(r.exitCode, 1);
        QCOMPARE(r.err, QStringLiteral("glint: %1: no camera named \"nope\"\n").arg(kBox));
        QVERIFY(!QFile::exists(dir.filePath("box.png")));
    }

    void strictRefusesTheFallback() {
        QTemporaryDir dir;
        const CliResult r = runGlint({"render", kBox, "--env", kEnv, "--strict", "--size", "32x32", "--spp", "1",
                                      "--out", dir.filePath("box.png")});
        QCOMPARE(r.exitCode, 1);
        QCOMPARE(r.err.count(kNoCamera), 1);
        QVERIFY(!QFile::exists(dir.filePath("box.png")));
    }
};

QTEST_GUILESS_MAIN(TestCliSceneDefaults)
#include "test_cli_scene_defaults.moc"
