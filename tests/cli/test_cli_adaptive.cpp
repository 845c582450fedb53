// Adaptive sampling at the command line (docs/CLI.md, "Adaptive sampling"): the project's
// render.adaptive drives `glint render`, --adaptive-threshold, --adaptive-min-spp and
// --adaptive-goal override it,
// the EXR's `samples` AOV holds each pixel's sample count and the header records the settings
// (hashed, so --resume re-renders when they change); bad values are usage errors naming the option.
#include "cli_runner.h"
#include "image_probe.h"
#include "scene_with_project.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>

namespace {

const QString kCornell = QStringLiteral(GLINT_RESOURCES_DIR "/scenes/cornell_box/cornell_box.gltf");
const QStringList kSmall = {"--size", "24x24", "--spp", "32", "--bounces", "2", "--aovs", "samples"};

// dir/s.gltf, the Cornell box, with `project` as its project file.
QString cornellWithProject(const QTemporaryDir& dir, const QByteArray& project) { return sceneWithProject(kCornell, dir, project); }

std::vector<float> channel(const ProbedImage& image, const std::string& name) {
    std::vector<float> plane;
    const auto c = std::size_t(std::find(image.channels.begin(), image.channels.end(), name) - image.channels.begin());
    if (c >= image.channels.size()) return plane;
    for (std::size_t i = c; i < image.pixels.size(); i += image.channels.size()) plane.push_back(image.pixels[i]);
    return plane;
}

} // namespace

class TestCliAdaptive : public QObject {
    Q_OBJECT

private slots:
    void theProjectsSettingDrivesRenderAndOptionsOverrideIt() {
        QTemporaryDir dir;
        const QString scene = cornellWithProject(dir, R"({"glint": 1, "render": {"adaptive": {"threshold": 0.3, "minSpp": 4}}})");
        const QString adaptive = dir.filePath("adaptive.exr");
        const CliResult r = runGlint(QStringList{"render", scene, "--out", adaptive} + kSmall);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const ProbedImage image = probeImage(adaptive);
        QVERIFY(image.ok);
        QCOMPARE(glintAttr(image, "adaptiveThreshold"), QString("0.3"));
        QCOMPARE(glintAttr(image, "adaptiveMinSpp"), QString("4"));
        const std::vector<float> samples = channel(image, "samples");
        QCOMPARE(samples.size(), std::size_t(24 * 24));
        QCOMPARE(*std::min_element(samples.begin(), samples.end()), 4.0f);  // the easiest tiles
        QCOMPARE(*std::max_element(samples.begin(), samples.end()), 32.0f); // the noisiest tiles

        // --adaptive-threshold 0 turns it off: every pixel takes every sample, nothing is recorded.
        const QString uniform = dir.filePath("uniform.exr");
        QCOMPARE(runGlint(QStringList{"render", scene, "--out", uniform, "--adaptive-threshold", "0"} + kSmall).exitCode, 0);
        const ProbedImage off = probeImage(uniform);
        for (const float s : channel(off, "samples")) QCOMPARE(s, 32.0f);
        QVERIFY(glintAttr(off, "adaptiveThreshold").isEmpty());
        QVERIFY(glintAttr(off, "settingsHash") != glintAttr(image, "settingsHash"));

        // --adaptive-min-spp moves the first test.
        const QString later = dir.filePath("later.exr");
        QCOMPARE(runGlint(QStringList{"render", scene, "--out", later, "--adaptive-min-spp", "16"} + kSmall).exitCode, 0);
        const std::vector<float> laterSamples = channel(probeImage(later), "samples");
        QCOMPARE(*std::min_element(laterSamples.begin(), laterSamples.end()), 16.0f);

        // --adaptive-goal mean changes the rule (its thresholds are far smaller), is recorded and
        // hashed; the project's goal applies where the option is left out.
        const QString mean = dir.filePath("mean.exr");
        QCOMPARE(runGlint(QStringList{"render", scene, "--out", mean, "--adaptive-goal", "mean", "--adaptive-threshold", "0.02"} + kSmall)
                     .exitCode,
                 0);
        const ProbedImage meanImage = probeImage(mean);
        QCOMPARE(glintAttr(meanImage, "adaptiveGoal"), QString("mean"));
        QVERIFY(glintAttr(image, "adaptiveGoal").isEmpty()); // even, the default, is not written
        QCOMPARE(glintAttr(meanImage, "adaptiveMinSpp"), QString("4")); // the project's
        const std::vector<float> meanSamples = channel(meanImage, "samples");
        const float meanFewest = *std::min_element(meanSamples.begin(), meanSamples.end());
        QVERIFY2(meanFewest >= 4.0f && meanFewest < *std::max_element(meanSamples.begin(), meanSamples.end()),
                 "tiles stop at different counts, none before the minimum");
        QVERIFY(meanSamples != samples); // another rule
        const QString meanScene =
            cornellWithProject(dir, R"({"glint": 1, "render": {"adaptive": {"threshold": 0.02, "minSpp": 4, "goal": "mean"}}})");
        const QString fromProject = dir.filePath("from_project.exr");
        QCOMPARE(runGlint(QStringList{"render", meanScene, "--out", fromProject} + kSmall).exitCode, 0);
        const ProbedImage fromProjectImage = probeImage(fromProject);
        QCOMPARE(glintAttr(fromProjectImage, "adaptiveGoal"), QString("mean"));
        QCOMPARE(glintAttr(fromProjectImage, "settingsHash"), glintAttr(meanImage, "settingsHash"));
        QCOMPARE(channel(fromProjectImage, "samples"), meanSamples);
    }

    void badValuesAreUsageErrors() {
        const CliResult threshold = runGlint({"render", kCornell, "--out", "x.exr", "--adaptive-threshold", "2"});
        QCOMPARE(threshold.exitCode, 2);
        QVERIFY2(threshold.err.contains("--adaptive-threshold"), qPrintable(threshold.err));
        const CliResult minimum = runGlint({"render", kCornell, "--out", "x.exr", "--adaptive-min-spp", "-1"});
        QCOMPARE(minimum.exitCode, 2);
        QVERIFY2(minimum.err.contains("--adaptive-min-spp"), qPrintable(minimum.err));
        const CliResult goal = runGlint({"render", kCornell, "--out", "x.exr", "--adaptive-goal", "median"});
        QCOMPARE(goal.exitCode, 2);
        QVERIFY2(goal.err.contains("--adaptive-goal"), qPrintable(goal.err));
        QTemporaryDir dir;
        const CliResult realTime = runGlint({"render", kCornell, "--out", dir.filePath("rt.exr"), "--aovs", "samples", "--config",
                                             "full", "--size", "8x8", "--spp", "1"});
        QCOMPARE(realTime.exitCode, 2);
        QCOMPARE(realTime.err.trimmed(), QString("glint: --aovs: the samples AOV needs the accumulate or reference configuration, not 'full'"));
    }
};

QTEST_GUILESS_MAIN(TestCliAdaptive)
#include "test_cli_adaptive.moc"
