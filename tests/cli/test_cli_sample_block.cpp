// Sample blocks at the command line (docs/CLI.md, "Sample blocks"): the project's render.sampleBlock
// drives `glint render` and --sample-block overrides it; the EXR header records the size (hashed, so
// --resume re-renders when it changes) and leaves it out when off, so older frames keep their hash;
// bad values are usage errors naming the option.
#include "cli_runner.h"
#include "image_probe.h"
#include "scene_with_project.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

namespace {

const QString kCornell = QStringLiteral(GLINT_RESOURCES_DIR "/scenes/cornell_box/cornell_box.gltf");
const QStringList kSmall = {"--size", "16x16", "--spp", "4", "--bounces", "2", "--aovs", "none"};

// dir/s.gltf, the Cornell box, with `project` as its project file.
QString cornellWithProject(const QTemporaryDir& dir, const QByteArray& project) { return sceneWithProject(kCornell, dir, project); }

} // namespace

class TestCliSampleBlock : public QObject {
    Q_OBJECT

private slots:
    void theProjectsSettingDrivesRenderAndTheOptionOverridesIt() {
        QTemporaryDir dir;
        const QString scene = cornellWithProject(dir, R"({"glint": 1, "render": {"sampleBlock": 4}})");
        const QString fromProject = dir.filePath("project.exr");
        const CliResult r = runGlint(QStringList{"render", scene, "--out", fromProject} + kSmall);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const ProbedImage blocks = probeImage(fromProject);
        QVERIFY(blocks.ok);
        QCOMPARE(glintAttr(blocks, "sampleBlock"), QString("4"));

        // The option on a project without the key gives the same setting, so the same hash and the
        // same pixels.
        QTemporaryDir plainDir;
        const QString plain = cornellWithProject(plainDir, R"({"glint": 1})");
        const QString fromOption = dir.filePath("option.exr");
        QCOMPARE(runGlint(QStringList{"render", plain, "--out", fromOption, "--sample-block", "4"} + kSmall).exitCode, 0);
        const ProbedImage option = probeImage(fromOption);
        QCOMPARE(glintAttr(option, "settingsHash"), glintAttr(blocks, "settingsHash"));
        QVERIFY(option.pixels == blocks.pixels);

        // --sample-block 1 turns it off: nothing recorded, another hash, other pixels.
        const QString off = dir.filePath("off.exr");
        QCOMPARE(runGlint(QStringList{"render", scene, "--out", off, "--sample-block", "1"} + kSmall).exitCode, 0);
        const ProbedImage own = probeImage(off);
        QVERIFY(glintAttr(own, "sampleBlock").isEmpty());
        QVERIFY(glintAttr(own, "settingsHash") != glintAttr(blocks, "settingsHash"));
        QVERIFY(own.pixels != blocks.pixels);
    }

    void badValuesAreUsageErrors() {
        for (const char* value : {"3", "16", "0"}) {
            const CliResult r = runGlint({"render", kCornell, "--out", "x.exr", "--sample-block", value});
            QCOMPARE(r.exitCode, 2);
            QVERIFY2(r.err.contains("--sample-block"), qPrintable(r.err));
        }
    }
};

QTEST_GUILESS_MAIN(TestCliSampleBlock)
#include "test_cli_sample_block.moc"
