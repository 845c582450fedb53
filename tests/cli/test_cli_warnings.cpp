// Renderer warnings on the command line: `glint render` of a scene whose texture file is missing
// renders (exit 0, the checker placeholder) and says so on stderr in the contract's format,
// `glint: warning: SCENE: texture FILE: ... [code]`, once. 32x32 px, 1 spp, llvmpipe.
#include "cli_runner.h"
#include "generated_scenes.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace glint;

class TestCliWarnings : public QObject {
    Q_OBJECT
private slots:
    void renderPrintsTheMissingTexture() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString scene = dir.filePath("missing.gltf");
        saveScene(test::missingTextureScene(), scene.toStdString());
        const CliResult r = runGlint({"render", scene, "--out", dir.filePath("out.png"), "--size", "32x32", "--spp", "1"});
        qInfo("stderr:\n%s", qPrintable(r.err));
        QCOMPARE(r.exitCode, 0);
        QVERIFY(QFile::exists(dir.filePath("out.png")));
        const QString expected = QStringLiteral("glint: warning: %1: texture %2: missing (shown as a checker) [texture-missing]")
                                         .arg(scene, QString::fromLatin1(test::kMissingTextureFile));
        QCOMPARE(r.err.count(expected), 1);
    }
};

QTEST_GUILESS_MAIN(TestCliWarnings)
#include "test_cli_warnings.moc"
