// The editor's export equals `glint render` for the same settings: the PNG byte for byte, the EXR
// channel for channel bit-exact with the same header attributes except the render time. Also:
// an animation's frames equal `glint render --animation` and encode into a video; cancel leaves no
// file, and bad settings are refused before anything starts.
// Scene: shapes under a grey sky and a camera, 48x32 px, 4 spp, accumulate, seed 0.
// The export plan (renderer headers, epoxy) before any Qt header.
#include "editor/export/export_plan.h"

#include "test_viewport_scene.h"

#include "editor/export/export_dialog.h"
#include "editor/export/export_job.h"
#include "scene/history/camera_path_commands.h"
#include "scene/history/node_commands.h"
#include "scene/history/settings_commands.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

using namespace glint;
using namespace glint::editor;

namespace {

struct ExrContents {
    std::vector<std::string> channels;
    std::vector<float> pixels;
    std::map<std::string, std::string> attributes;
};

ExrContents readExr(const std::string& file) {
    ExrContents c;
    auto in = OIIO::ImageInput::open(file);
    if (!in) return c;
    const OIIO::ImageSpec& spec = in->spec();
    c.channels = spec.channelnames;
    c.pixels.resize(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(spec.nchannels));
    in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, c.pixels.data());
    for (const auto& p : spec.extra_attribs) c.attributes[p.name().string()] = p.get_string();
    return c;
}

QByteArray bytesOf(const QString& file) {
    QFile f(file);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

} // namespace

class TestExportEqualsCli : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        dir_.setAutoRemove(qEnvironmentVariableIsEmpty("GLINT_KEEP_TEST_FILES"));
        test::buildShapesScene(document_);
        Node camera;
        camera.name = "cam";
        camera.local.translation = {0.0f, 0.3f, 4.0f};
        camera.component = Camera{};
        document_.push(std::make_unique<AddNode>(std::move(camera)));
        QCOMPARE(document_.saveAs(dir_.filePath("scene.gltf")), QString());
    }

    void stillEqualsCommandLine_data() {
        QTest::addColumn<QString>("extension");
        QTest::addColumn<QString>("passes");
        QTest::newRow("exr") << "exr" << "";
        QTest::newRow("exr with render passes") << "exr" << "all";
        QTest::newRow("png") << "png" << "";
    }

    void stillEqualsCommandLine() {
        QFETCH(QString, extension);
        QFETCH(QString, passes);
        const QString editorFile = dir_.filePath("editor." + extension), cliFile = dir_.filePath("cli." + extension);
        ExportSettings s;
        s.sceneFile = document_.filePath().toStdString();
        s.out = editorFile.toStdString();
        s.width = 48;
        s.height = 32;
        s.spp = 4;
        s.configuration = "accumulate";
        s.passes = passes.toStdString();
        ExportController controller;
        QSignalSpy finished(&controller, &ExportController::finished);
        QSignalSpy running(&controller, &ExportController::running);
        controller.start(document_.scene(), s);
        QVERIFY(finished.wait(60000));
        QCOMPARE(finished.first().at(0).toString(), QString());
        QCOMPARE(running.size(), 2); // paused the viewport and resumed it
        QCOMPARE(controller.files(), QStringList{editorFile});

        QProcess cli;
        cli.start(GLINT_EXECUTABLE, {"render", document_.filePath(), "--size", "48x32", "--spp", "4", "--config", "accumulate",
                                     "--out", cliFile, "--passes", passes.isEmpty() ? QString("none") : passes});
        QVERIFY(cli.waitForFinished(60000));
        QVERIFY2(cli.exitStatus() == QProcess::NormalExit && cli.exitCode() == 0,
                 qPrintable(QString("exit %1: %2").arg(cli.exitCode()).arg(QString::fromUtf8(cli.readAllStandardError()))));

        if (extension == "png") {
            const QByteArray a = bytesOf(editorFile), b = bytesOf(cliFile);
            QVERIFY(!a.isEmpty());
            QVERIFY(a == b);
            return;
        }
        ExrContents a = readExr(editorFile.toStdString()), b = readExr(cliFile.toStdString());
        QVERIFY(!a.pixels.empty());
        QCOMPARE(a.channels, b.channels);
        QCOMPARE(int(std::count(a.channels.begin(), a.channels.end(), "Vector.X")), passes.isEmpty() ? 0 : 1);
        QVERIFY(std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0 && a.pixels.size() == b.pixels.size());
        QVERIFY(a.attributes.count("glint:renderTimeMs") && a.attributes.count("glint:settingsHash"));
        // The render time is the one header entry allowed to differ (docs/CLI.md).
        a.attributes.erase("glint:renderTimeMs");
        b.attributes.erase("glint:renderTimeMs");
        for (const auto& [key, value] : a.attributes)
            if (!b.attributes.count(key) || b.attributes.at(key) != value)
                qWarning("attribute %s: editor '%s', command line '%s'", key.c_str(), value.c_str(),
                         b.attributes.count(key) ? b.attributes.at(key).c_str() : "(none)");
        QCOMPARE(a.attributes, b.attributes);
    }

    void animationFramesEqualCommandLineAndEncode() {
        // A camera path over 2 frames at 24 fps: frames 0, 1, 2.
        const NodeId camera = *document_.scene().findByName("cam");
        CameraKey a;
        a.position = {0.0, 0.3, 4.0};
        CameraKey b = a;
        b.time = 2.0 / 24.0;
        b.position = {0.5, 0.3, 4.0};
        document_.push(std::make_unique<AddCameraKey>(camera, a));
        document_.push(std::make_unique<AddCameraKey>(camera, b));
        QCOMPARE(document_.save(), QString());

        ExportSettings s;
        s.sceneFile = document_.filePath().toStdString();
        s.out = dir_.filePath("anim/editor_####.png").toStdString();
        s.width = 32;
        s.height = 24;
        s.spp = 2;
        s.animation = true;
        s.firstFrame = 0;
        s.lastFrame = 2;
        s.video = dir_.filePath("anim/editor.mkv").toStdString();
        s.encoder = GLINT_EXECUTABLE;
        QVERIFY(QDir().mkpath(dir_.filePath("anim")));
        ExportController controller;
        QSignalSpy finished(&controller, &ExportController::finished);
        controller.start(document_.scene(), s);
        QVERIFY(finished.wait(120000));
        QCOMPARE(finished.first().at(0).toString(), QString());
        QCOMPARE(controller.files().size(), 4); // three frames and the video
        QVERIFY(QFileInfo(dir_.filePath("anim/editor.mkv")).size() > 0);

        QProcess cli;
        cli.start(GLINT_EXECUTABLE, {"render", document_.filePath(), "--animation", "--frames", "0-2", "--size", "32x24", "--spp", "2",
                                     "--out", dir_.filePath("anim/cli_####.png")});
        QVERIFY(cli.waitForFinished(120000));
        QVERIFY2(cli.exitStatus() == QProcess::NormalExit && cli.exitCode() == 0,
                 qPrintable(QString("exit %1: %2").arg(cli.exitCode()).arg(QString::fromUtf8(cli.readAllStandardError()))));
        for (int k = 0; k <= 2; ++k) {
            const QByteArray mine = bytesOf(dir_.filePath(QString("anim/editor_%1.png").arg(k, 4, 10, QChar('0'))));
            QVERIFY(!mine.isEmpty());
            QVERIFY2(mine == bytesOf(dir_.filePath(QString("anim/cli_%1.png").arg(k, 4, 10, QChar('0')))), qPrintable(QString::number(k)));
        }
    }

    void cancelWritesNothing() {
        ExportSettings s;
        s.sceneFile = document_.filePath().toStdString();
        s.out = dir_.filePath("cancelled.exr").toStdString();
        s.width = 64;
        s.height = 64;
        s.spp = 100000;
        ExportController controller;
        QSignalSpy finished(&controller, &ExportController::finished);
        QSignalSpy progress(&controller, &ExportController::progress);
        controller.start(document_.scene(), s);
        QVERIFY(progress.wait(60000)); // rendering has begun
        controller.cancel();
        QVERIFY(finished.wait(60000));
        QCOMPARE(finished.first().at(1).toBool(), true);
        QVERIFY(!QFile::exists(dir_.filePath("cancelled.exr")));
    }

    void badSettingsAreRefusedUpFront() {
        ExportSettings s;
        s.sceneFile = document_.filePath().toStdString();
        s.out = dir_.filePath("x.exr").toStdString();
        s.configuration = "nonsense";
        ExportController controller;
        QVERIFY_THROWS_EXCEPTION(std::runtime_error, controller.start(document_.scene(), s));
        QVERIFY(!controller.isRunning());
        s.configuration = "accumulate";
        s.animation = true;
        s.out = dir_.filePath("no_pattern.exr").toStdString();
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, controller.start(document_.scene(), s));
        // Render passes: an unknown name, and passes with a real-time configuration.
        s.animation = false;
        s.out = dir_.filePath("x.exr").toStdString();
        s.passes = "Emit,Shadow";
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, controller.start(document_.scene(), s));
        s.passes = "Emit";
        s.configuration = "full";
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, controller.start(document_.scene(), s));
        QVERIFY(!controller.isRunning());
    }

    void dialogFieldsRoundTrip() {
        ExportDialog dialog(document_, ExportDialog::Kind::Animation);
        ExportSettings s;
        s.out = dir_.filePath("shot_####.png").toStdString();
        s.width = 320;
        s.height = 200;
        s.spp = 9;
        s.seed = 5;
        s.configuration = "reference";
        s.aovs = "albedo,depth";
        s.passes = "Emit,Vector";
        s.firstFrame = 3;
        s.lastFrame = 7;
        dialog.setSettings(s);
        const ExportSettings back = dialog.settings();
        QCOMPARE(QString::fromStdString(back.out.string()), QString::fromStdString(s.out.string()));
        QCOMPARE(back.width, 320);
        QCOMPARE(back.height, 200);
        QCOMPARE(back.spp, 9);
        QCOMPARE(back.seed, 5u);
        QCOMPARE(back.configuration, std::string("reference"));
        QCOMPARE(back.aovs, std::string("albedo,depth"));
        QCOMPARE(back.passes, std::string("Emit,Vector"));
        QVERIFY(back.animation);
        QCOMPARE(back.firstFrame, 3);
        QCOMPARE(back.lastFrame, 7);
        QCOMPARE(QString::fromStdString(back.sceneFile.string()), document_.filePath());
        QVERIFY(back.video.empty());
    }

    void framePathsAndTimes() {
        QCOMPARE(QString::fromStdString(framePath("out/shot_####.exr", 7).string()), QString("out/shot_0007.exr"));
        QCOMPARE(QString::fromStdString(framePath("shot_#.png", 123).string()), QString("shot_123.png"));
        ExportSettings s;
        s.fpsNumerator = 24000;
        s.fpsDenominator = 1001;
        QCOMPARE(exportFrameTime(document_.scene(), s, 24), 24.0 * 1001.0 / 24000.0);
    }

    // The dialog opens with the project's output block where it fits the kind (a still's path in the
    // still dialog, not in the animation one), and after an export with what that export used.
    void dialogOpensWithTheProjectOutputThenTheLastExport() {
        ProjectSettings settings = document_.scene().settings;
        settings.output.path = "renders/shot.png";
        settings.output.aovs = "none";
        settings.output.passes = "light";
        document_.push(std::make_unique<SetProjectSettings>(settings));
        const QString expected = QFileInfo(document_.filePath()).absolutePath() + "/renders/shot.png";
        {
            ExportDialog still(document_, ExportDialog::Kind::Still);
            QCOMPARE(QString::fromStdString(still.settings().out.string()), expected);
            QCOMPARE(still.settings().aovs, std::string("none"));
            QCOMPARE(still.settings().passes, std::string("light"));
            ExportDialog animation(document_, ExportDialog::Kind::Animation);
            QVERIFY(QString::fromStdString(animation.settings().out.string()).contains("####"));
        }
        ExportDialog dialog(document_, ExportDialog::Kind::Still);
        ExportSettings chosen = dialog.settings();
        chosen.out = dir_.filePath("chosen.png").toStdString();
        chosen.width = 24;
        chosen.height = 16;
        chosen.spp = 3;
        chosen.passes = "Emit";
        dialog.setSettings(chosen);
        QSignalSpy finished(&dialog.controller(), &ExportController::finished);
        dialog.startExport();
        QVERIFY(finished.wait(60000));
        QVERIFY(QFile::exists(dir_.filePath("chosen.png")));
        ExportDialog again(document_, ExportDialog::Kind::Still);
        QCOMPARE(QString::fromStdString(again.settings().out.string()), dir_.filePath("chosen.png"));
        QCOMPARE(again.settings().width, 24);
        QCOMPARE(again.settings().spp, 3);
        QCOMPARE(again.settings().passes, std::string("Emit"));
        document_.undo();
    }

private:
    QTemporaryDir dir_;
    Document document_;
};

QTEST_MAIN(TestExportEqualsCli)
#include "test_export_equals_cli.moc"
