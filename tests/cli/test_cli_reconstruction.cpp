// The project's reconstruction parameters reach `glint render`: SVGF with 1 a-trous iteration and
// with 5 gives different pixels, the same value gives the same pixels, and a value out of range is
// an error naming the key.
#include "cli_runner.h"

#include <QFile>
#include <QImage>
#include <QTemporaryDir>
#include <QtTest>

namespace {
const QString cornell = QStringLiteral(GLINT_RESOURCES_DIR "/scenes/cornell_box/cornell_box.gltf");

bool writeText(const QString& path, const QByteArray& text) {
    QFile f(path);
    return f.open(QIODevice::WriteOnly | QIODevice::Truncate) && f.write(text) == text.size();
}

// A copy of the Cornell box in `dir` whose project file sets the SVGF iterations (0: no key).
QString sceneWithIterations(const QTemporaryDir& dir, const QString& name, int iterations) {
    const QString scene = dir.filePath(name + ".gltf");
    QFile::copy(cornell, scene);
    QByteArray svgf = iterations > 0 ? QByteArray(R"(, "svgf": {"iterations": )") + QByteArray::number(iterations) + "}" : "";
    writeText(dir.filePath(name + ".glint.json"),
              R"({"glint": 1, "scene": ")" + name.toUtf8() + R"(.gltf", "render": {"configuration": "full")" + svgf + "}}\n");
    return scene;
}

// One 32x32 frame of the Full configuration (SVGF + TAA), 1 sample per pixel, seed 0; the pixels
// (the files differ anyway: their metadata name the scene file).
QImage renderPng(const QTemporaryDir& dir, const QString& scene, const QString& out) {
    const auto r = runGlint({"render", scene, "--size", "32x32", "--spp", "1", "--out", dir.filePath(out)});
    if (r.exitCode != 0) qWarning("%s", qPrintable(r.err));
    return r.exitCode == 0 ? QImage(dir.filePath(out)).convertToFormat(QImage::Format_RGBA8888) : QImage();
}
} // namespace

class TestCliReconstruction : public QObject {
    Q_OBJECT
private slots:
    void atrousIterationsChangeTheImage() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QImage one = renderPng(dir, sceneWithIterations(dir, "one", 1), "one.png");
        const QImage five = renderPng(dir, sceneWithIterations(dir, "five", 5), "five.png");
        const QImage fiveAgain = renderPng(dir, sceneWithIterations(dir, "again", 5), "again.png");
        const QImage defaults = renderPng(dir, sceneWithIterations(dir, "defaults", 0), "defaults.png");
        QVERIFY(!one.isNull() && !five.isNull());
        // Tolerance 0 both ways: any pixel differs, and the same values give identical pixels.
        int differing = 0;
        for (int y = 0; y < five.height(); ++y)
            for (int x = 0; x < five.width(); ++x) differing += one.pixel(x, y) != five.pixel(x, y);
        QVERIFY2(differing > 0, "1 and 5 a-trous iterations rendered the same pixels");
        QCOMPARE(fiveAgain, five); // same project values: the same pixels
        QCOMPARE(defaults, five);  // 5 is the default: writing it changes nothing
    }

    void badValueIsAnErrorNamingTheKey() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString scene = sceneWithIterations(dir, "bad", 11);
        const auto r = runGlint({"render", scene, "--size", "8x8", "--spp", "1", "--out", dir.filePath("bad.png")});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("render.svgf.iterations") && r.err.contains("1 to 10"), qPrintable(r.err));
        QVERIFY(!QFile::exists(dir.filePath("bad.png")));
    }
};

QTEST_GUILESS_MAIN(TestCliReconstruction)
#include "test_cli_reconstruction.moc"
