// `glint render --time T` poses node animations at T, for stills and animation frames alike: a
// box animated from x = -1 (t = 0) to x = +1 (t = 1 s) renders at --time 0.5 exactly like the
// same scene without the animation and the box at x = 0 (Accumulate, same seed: bit for bit).
// Number options refuse NaN, infinities and values out of range (exit 2), and a huge exposure
// is white, not NaN-black. 24x24 px, llvmpipe.
#include "cli_runner.h"
#include "image_probe.h"

#include "scene/core/scene.h"
#include "scene/io/scene_io.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace glint;

namespace {

// A unit box at `x` seen by a camera 4 m away, under a grey sky; with `animated`, a linear
// animation moves it from x = -1 to +1 over one second.
Scene boxScene(float x, bool animated) {
    Scene scene;
    scene.settings.environment.color = glm::vec3(0.6f);
    Material red;
    red.baseColorFactor = {0.8f, 0.1f, 0.1f, 1.0f};
    Shape box;
    box.kind = ShapeKind::Box;
    box.material = scene.materials.add(red);
    Node boxNode;
    boxNode.name = "box";
    boxNode.local.translation = {x, 0.0f, 0.0f};
    boxNode.component = box;
    const NodeId id = scene.addNode(std::move(boxNode));
    Node camera;
    camera.name = "camera";
    camera.local.translation = {0.0f, 0.0f, 4.0f};
    camera.component = Camera{};
    scene.addNode(std::move(camera));
    if (animated) {
        Animation move;
        move.name = "move";
        move.channels.push_back({id, AnimationPath::Translation, Interpolation::Linear, {0.0f, 1.0f}, {-1, 0, 0, 1, 0, 0}});
        scene.animations.add(std::move(move));
    }
    return scene;
}

QString write(const QTemporaryDir& dir, const QString& name, const Scene& scene) {
    const QString file = dir.filePath(name);
    saveScene(scene, file.toStdString());
    return file;
}

std::vector<float> render(const QStringList& args) {
    const CliResult r = runGlint(QStringList{"render"} + args + QStringList{"--size", "24x24", "--spp", "2", "--seed", "3", "--config", "accumulate"});
    if (r.exitCode != 0) qWarning("%s", qPrintable(r.err));
    return r.exitCode == 0 ? probeImage(args.at(args.indexOf("--out") + 1)).pixels : std::vector<float>{};
}

} // namespace

class TestCliTime : public QObject {
    Q_OBJECT
private slots:
    void stillAtTimePosesTheAnimation() {
        QTemporaryDir dir;
        const QString animated = write(dir, "animated.gltf", boxScene(0.0f, true));
        const QString moved = write(dir, "moved.gltf", boxScene(0.0f, false));
        const auto atHalf = render({animated, "--time", "0.5", "--out", dir.filePath("half.exr")});
        const auto reference = render({moved, "--out", dir.filePath("moved.exr")});
        const auto atZero = render({animated, "--time", "0", "--out", dir.filePath("zero.exr")});
        QVERIFY(!atHalf.empty() && atHalf.size() == reference.size());
        QVERIFY(atHalf == reference);
        QVERIFY(atZero != reference); // the box really moves
    }

    void animationFramePosesTheAnimation() {
        QTemporaryDir dir;
        const QString animated = write(dir, "animated.gltf", boxScene(0.0f, true));
        const QString moved = write(dir, "moved.gltf", boxScene(0.0f, false));
        // Frame 12 at 24 fps is t = 0.5 s; animation frame k renders with seed + k.
        const CliResult r = runGlint({"render", animated, "--animation", "--frames", "12-12", "--fps", "24", "--size", "24x24",
                                      "--spp", "2", "--seed", "0", "--config", "accumulate", "--out", dir.filePath("f_####.exr")});
        QCOMPARE(r.exitCode, 0);
        const auto frame = probeImage(dir.filePath("f_0012.exr")).pixels;
        const CliResult still = runGlint({"render", moved, "--size", "24x24", "--spp", "2", "--seed", "12", "--config",
                                          "accumulate", "--out", dir.filePath("moved.exr")});
        QCOMPARE(still.exitCode, 0);
        QVERIFY(!frame.empty());
        QVERIFY(frame == probeImage(dir.filePath("moved.exr")).pixels);
    }

    void numbersOutOfRangeAreUsageErrors_data() {
        QTest::addColumn<QString>("option");
        QTest::addColumn<QString>("value");
        QTest::addColumn<QString>("message");
        QTest::newRow("time nan") << "--time" << "nan" << "glint: --time: nan is not in -100000 to 100000";
        QTest::newRow("time inf") << "--time" << "inf" << "glint: --time: inf is not in -100000 to 100000";
        QTest::newRow("exposure huge") << "--exposure" << "1e308" << "glint: --exposure: 1e308 is not in -64 to 64";
        QTest::newRow("exposure text") << "--exposure" << "abc" << "glint: --exposure: 'abc' is not a number";
    }

    void numbersOutOfRangeAreUsageErrors() {
        QFETCH(QString, option);
        QFETCH(QString, value);
        QFETCH(QString, message);
        QTemporaryDir dir;
        const QString scene = write(dir, "moved.gltf", boxScene(0.0f, false));
        const CliResult r = runGlint({"render", scene, option, value, "--out", dir.filePath("x.png")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.startsWith(message), qPrintable(r.err));
        QVERIFY(!QFile::exists(dir.filePath("x.png")));
    }

    void hugeExposureIsWhite() {
        QTemporaryDir dir;
        const QString scene = write(dir, "moved.gltf", boxScene(0.0f, false));
        const QStringList args{"render", scene, "--exposure", "64", "--size", "8x8", "--spp", "1"};
        QCOMPARE(runGlint(args + QStringList{"--out", dir.filePath("white.png")}).exitCode, 0);
        QCOMPARE(runGlint(args + QStringList{"--out", dir.filePath("linear.exr")}).exitCode, 0);
        const ProbedImage png = probeImage(dir.filePath("white.png"));
        const ProbedImage exr = probeImage(dir.filePath("linear.exr"));
        QVERIFY(png.ok && exr.ok && png.channels.size() == 4);
        // ACES saturates: every channel with light in it is white. (A rough metal's sample can
        // carry no light at all: those stay black, as without the exposure.)
        int white = 0;
        for (int p = 0; p < png.width * png.height; ++p)
            for (int c = 0; c < 3; ++c) {
                const float radiance = exr.pixels[std::size_t(p) * exr.channels.size() + std::size_t(c)];
                const float shown = png.pixels[std::size_t(p) * 4 + std::size_t(c)];
                QCOMPARE(shown, radiance > 0.0f ? 1.0f : 0.0f);
                white += radiance > 0.0f;
            }
        QVERIFY(white > 3 * 8 * 8 / 2);
    }
};

QTEST_GUILESS_MAIN(TestCliTime)
#include "test_cli_time.moc"
