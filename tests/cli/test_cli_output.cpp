// glint render/encode against docs/CLI.md and issue "Output": EXR layers and metadata, --time,
// animations with resume, shards identical to one run, signals, bad input, and videos (ffprobe).
#include "cli_runner.h"
#include "image_probe.h"

#include "renderer/output/tonemap_cpu.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QThread>
#include <QtTest>

#include <csignal>

#include <signal.h>

namespace {

const QString cornell = QStringLiteral(GLINT_RESOURCES_DIR "/scenes/cornell_box/cornell_box.gltf");
const QString dolly = QStringLiteral(GLINT_RESOURCES_DIR "/farm/cornell_dolly.gltf"); // 1 s camera path
const QStringList tiny = {"--size", "32x32", "--spp", "1"};

QByteArray readAll(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// Every file in a folder, hidden ones too (temporary names start with a dot).
QStringList filesIn(const QString& folder) {
    return QDir(folder).entryList(QDir::Files | QDir::Hidden, QDir::Name);
}

QJsonObject probeVideo(const QString& file) {
    QProcess p;
    p.start("ffprobe", {"-v", "error", "-select_streams", "v:0", "-count_frames", "-show_entries",
                        "stream=codec_name,width,height,pix_fmt,nb_read_frames,r_frame_rate,color_space,color_primaries,"
                        "color_transfer",
                        "-of", "json", file});
    p.waitForFinished(60000);
    const auto streams = QJsonDocument::fromJson(p.readAllStandardOutput()).object()["streams"].toArray();
    return streams.isEmpty() ? QJsonObject() : streams[0].toObject();
}

int countOf(const QString& text, const QString& word) { return text.count(word); }

} // namespace

class TestCliOutput : public QObject {
    Q_OBJECT
private slots:
    void stillExrHasLayersAndMetadata() {
        QTemporaryDir dir;
        const QString exr = dir.filePath("c.exr");
        auto r = runGlint(QStringList{"render", cornell, "--out", exr, "--size", "16x16", "--spp", "2"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const ProbedImage image = probeImage(exr);
        QVERIFY(image.ok);
        const std::vector<std::string> expected = {"R", "G", "B", "A", "albedo.R", "albedo.G", "albedo.B",
                                                   "N.X", "N.Y", "N.Z", "Z", "id"};
        QCOMPARE(sorted(image.channels), sorted(expected));
        for (const char* key : {"scene", "camera", "spp", "seed", "configuration", "version", "settingsHash", "renderTimeMs"})
            QVERIFY2(!glintAttr(image, key).isEmpty(), key);
        QCOMPARE(glintAttr(image, "scene"), QString("cornell_box.gltf"));
        QCOMPARE(glintAttr(image, "spp"), QString("2"));
        QCOMPARE(glintAttr(image, "seed"), QString("0"));
        QCOMPARE(glintAttr(image, "settingsHash").size(), 16);

        // The same settings give the same hash; other settings another.
        const QString again = dir.filePath("again.exr"), other = dir.filePath("other.exr");
        QCOMPARE(runGlint({"render", cornell, "--out", again, "--size", "16x16", "--spp", "2"}).exitCode, 0);
        QCOMPARE(runGlint({"render", cornell, "--out", other, "--size", "16x16", "--spp", "3"}).exitCode, 0);
        QCOMPARE(glintAttr(probeImage(again), "settingsHash"), glintAttr(image, "settingsHash"));
        QVERIFY(glintAttr(probeImage(other), "settingsHash") != glintAttr(image, "settingsHash"));

        // The render time is the only header entry that may differ between identical renders
        // (docs/CLI.md): no wall-clock date may leak in.
        std::map<std::string, std::string> first = image.attributes, second = probeImage(again).attributes;
        first.erase("glint:renderTimeMs");
        second.erase("glint:renderTimeMs");
        QVERIFY(!first.contains("DateTime"));
        QVERIFY(first == second);
        QCOMPARE(probeImage(again).pixels, image.pixels);
    }

    void aovListSelectsLayers() {
        QTemporaryDir dir;
        const QString none = dir.filePath("none.exr"), some = dir.filePath("some.exr");
        QCOMPARE(runGlint({"render", cornell, "--out", none, "--size", "8x8", "--spp", "2", "--aovs", "none"}).exitCode, 0);
        QCOMPARE(sorted(probeImage(none).channels), sorted({"R", "G", "B", "A"}));
        QCOMPARE(runGlint({"render", cornell, "--out", some, "--size", "8x8", "--spp", "2", "--aovs", "depth,variance"}).exitCode, 0);
        QCOMPARE(sorted(probeImage(some).channels), sorted({"R", "G", "B", "A", "Z", "variance.R", "variance.G", "variance.B"}));
        const CliResult unknown = runGlint({"render", cornell, "--out", none, "--aovs", "albedo,fur"});
        QCOMPARE(unknown.exitCode, 2);
        QVERIFY2(unknown.err.contains("unknown AOV 'fur'"), qPrintable(unknown.err));
    }

    void timeRendersTheCameraPath() {
        QTemporaryDir dir;
        const QString start = dir.filePath("t0.exr"), end = dir.filePath("t1.exr");
        QCOMPARE(runGlint(QStringList{"render", dolly, "--out", start, "--time", "0"} + tiny).exitCode, 0);
        QCOMPARE(runGlint(QStringList{"render", dolly, "--out", end, "--time", "1"} + tiny).exitCode, 0);
        const ProbedImage a = probeImage(start), b = probeImage(end);
        QCOMPARE(glintAttr(b, "time"), QString("1"));
        QVERIFY(a.ok && b.ok && a.pixels != b.pixels); // the camera moved
    }

    void pngIsTheExrThroughTheDisplayTransform() {
        QTemporaryDir dir;
        const QString png = dir.filePath("c.png"), exr = dir.filePath("c.exr");
        const QStringList common = {"--size", "16x16", "--spp", "2", "--exposure", "0.5"};
        QCOMPARE(runGlint(QStringList{"render", cornell, "--out", png} + common).exitCode, 0);
        QCOMPARE(runGlint(QStringList{"render", cornell, "--out", exr} + common).exitCode, 0);
        const ProbedImage linear = probeImage(exr), shown = probeImage(png);
        QCOMPARE(glintAttr(linear, "tonemap"), QString("aces"));
        std::vector<float> rgba;
        for (std::size_t i = 0; i < linear.pixels.size(); i += linear.channels.size())
            rgba.insert(rgba.end(), linear.pixels.begin() + std::ptrdiff_t(i), linear.pixels.begin() + std::ptrdiff_t(i + 4));
        const auto bytes = glint::video::tonemapToSrgb8(rgba, glintAttr(linear, "exposureEv").toFloat(), glint::Tonemapper::AcesFitted);
        QCOMPARE(bytes.size(), shown.pixels.size());
        int worst = 0;
        for (std::size_t i = 0; i < bytes.size(); ++i)
            worst = std::max(worst, std::abs(int(bytes[i]) - int(std::lround(shown.pixels[i] * 255.0f))));
        QVERIFY2(worst <= 1, qPrintable(QString("max difference %1 codes (tolerance 1)").arg(worst)));
    }

    void animationWritesResumesAndReRendersStaleFrames() {
        QTemporaryDir dir;
        QDir(dir.path()).mkdir("f");
        const QString pattern = dir.filePath("f/shot_####.exr");
        const QStringList args = QStringList{"render", dolly, "--animation", "--frames", "0-3", "--out", pattern} + tiny;
        auto r = runGlint(args);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(filesIn(dir.filePath("f")),
                 (QStringList{"shot_0000.exr", "shot_0001.exr", "shot_0002.exr", "shot_0003.exr"}));
        QVERIFY2(r.err.contains("ETA"), qPrintable(r.err));
        const ProbedImage third = probeImage(dir.filePath("f/shot_0002.exr"));
        QCOMPARE(glintAttr(third, "frame"), QString("2"));
        QCOMPARE(glintAttr(third, "time").toDouble(), 2.0 / 24.0);
        QCOMPARE(glintAttr(third, "seed"), QString("2")); // seed + frame number

        auto again = runGlint(args);
        QCOMPARE(again.exitCode, 0);
        QCOMPARE(countOf(again.err, " kept: "), 4);

        // A frame cut short by a crash is not complete: it is rendered again, the others kept.
        QFile cut(dir.filePath("f/shot_0002.exr"));
        QVERIFY(cut.resize(cut.size() / 2));
        auto repaired = runGlint(args);
        QCOMPARE(repaired.exitCode, 0);
        QCOMPARE(countOf(repaired.err, " kept: "), 3);
        QVERIFY(repaired.err.contains("frame 2 (3/4) wrote"));
        QVERIFY(probeImage(dir.filePath("f/shot_0002.exr")).ok);

        // Frames rendered with other settings are stale: all rendered again.
        auto stale = runGlint(QStringList{"render", dolly, "--animation", "--frames", "0-3", "--out", pattern, "--size",
                                          "32x32", "--spp", "2"});
        QCOMPARE(stale.exitCode, 0);
        QCOMPARE(countOf(stale.err, " kept: "), 0);
        QCOMPARE(glintAttr(probeImage(dir.filePath("f/shot_0001.exr")), "spp"), QString("2"));
        auto forced = runGlint(QStringList{"render", dolly, "--animation", "--frames", "0-1", "--out", pattern, "--size",
                                           "32x32", "--spp", "2", "--no-resume"});
        QCOMPARE(countOf(forced.err, " kept: "), 0);
        QCOMPARE(filesIn(dir.filePath("f")).size(), 4);
    }

    void shardsAndJobArraysMatchOneRun() {
        QTemporaryDir dir;
        const QString one = dir.filePath("one_####.exr"), sharded = dir.filePath("shard_####.exr");
        const QStringList base = QStringList{"render", dolly, "--animation", "--frames", "0-5"} + tiny;
        QCOMPARE(runGlint(base + QStringList{"--out", one}).exitCode, 0);
        QCOMPARE(runGlint(base + QStringList{"--out", sharded, "--shard", "0/3"}).exitCode, 0);
        QCOMPARE(filesIn(dir.path()).filter("shard_"), (QStringList{"shard_0000.exr", "shard_0003.exr"}));
        // Slurm array 10-12: task 11 is shard 1 of 3. Kubernetes: index 2 with --shards 3.
        QCOMPARE(runGlint(base + QStringList{"--out", sharded},
                          {"SLURM_ARRAY_TASK_ID=11", "SLURM_ARRAY_TASK_MIN=10", "SLURM_ARRAY_TASK_COUNT=3"})
                     .exitCode,
                 0);
        QCOMPARE(runGlint(base + QStringList{"--out", sharded, "--shards", "3"}, {"JOB_COMPLETION_INDEX=2"}).exitCode, 0);
        for (int f = 0; f <= 5; ++f) {
            const QString n = QString("_%1.exr").arg(f, 4, 10, QChar('0'));
            const ProbedImage a = probeImage(dir.filePath("one" + n)), b = probeImage(dir.filePath("shard" + n));
            QVERIFY2(a.ok && b.ok, qPrintable(n));
            QVERIFY2(a.pixels == b.pixels, qPrintable("frame " + n + " differs between one run and shards (bit-exact)"));
        }
    }

    void historyChunksMatchInShardsAndAlone() {
        // A temporally filtered configuration: chunks of 2 frames, 1 warm-up frame, so 6 frames
        // make 3 chunks and 2 shards split them 2 + 1.
        QTemporaryDir dir;
        const QStringList base = {"render", dolly, "--animation", "--size", "24x24", "--config", "full", "--chunk", "2",
                                  "--warmup", "1"};
        auto one = runGlint(base + QStringList{"--frames", "0-5", "--out", dir.filePath("one_####.exr")});
        QVERIFY2(one.exitCode == 0, qPrintable(one.err));
        QVERIFY2(one.err.contains("6 frames in 3 chunks"), qPrintable(one.err));
        for (const char* shard : {"0/2", "1/2"})
            QCOMPARE(runGlint(base + QStringList{"--frames", "0-5", "--shard", shard, "--out", dir.filePath("sh_####.exr")}).exitCode, 0);
        QCOMPARE(runGlint(base + QStringList{"--frames", "3", "--out", dir.filePath("alone_####.exr")}).exitCode, 0);
        auto noWarmup = runGlint(QStringList{"render", dolly, "--animation", "--size", "24x24", "--config", "full", "--chunk",
                                             "2", "--warmup", "0", "--frames", "3", "--out", dir.filePath("cold_####.exr")});
        QCOMPARE(noWarmup.exitCode, 0);
        for (int f = 0; f <= 5; ++f) {
            const QString n = QString("_%1.exr").arg(f, 4, 10, QChar('0'));
            const ProbedImage a = probeImage(dir.filePath("one" + n)), b = probeImage(dir.filePath("sh" + n));
            QVERIFY2(a.ok && b.ok && a.pixels == b.pixels, qPrintable("frame" + n + ": one run and shards differ (bit-exact)"));
        }
        const ProbedImage whole = probeImage(dir.filePath("one_0003.exr"));
        QVERIFY2(whole.pixels == probeImage(dir.filePath("alone_0003.exr")).pixels, "frame 3 alone differs from frame 3 in the run");
        QVERIFY2(whole.pixels != probeImage(dir.filePath("cold_0003.exr")).pixels, "the warm-up frame had no effect");
        QCOMPARE(glintAttr(whole, "configuration"), QString("full"));
        auto resumed = runGlint(base + QStringList{"--frames", "0-5", "--out", dir.filePath("one_####.exr")});
        QCOMPARE(countOf(resumed.err, " kept: "), 6);
    }

    void stopSignalFinishesOrDiscardsTheFrame() {
        QTemporaryDir dir;
        QProcess p;
        p.start(QStringLiteral(GLINT_EXECUTABLE),
                QStringList{"render", dolly, "--animation", "--frames", "0-400", "--out", dir.filePath("s_####.exr")} + tiny);
        p.setReadChannel(QProcess::StandardError);
        QVERIFY(p.waitForStarted());
        QByteArray err;
        while (!err.contains(" wrote ") && p.waitForReadyRead(60000)) err += p.readAllStandardError();
        QVERIFY2(err.contains(" wrote "), err.constData());
        ::kill(pid_t(p.processId()), SIGTERM);
        QVERIFY(p.waitForFinished(60000));
        err += p.readAllStandardError();
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QCOMPARE(p.exitCode(), 128 + SIGTERM);
        const QStringList files = filesIn(dir.path());
        QVERIFY(!files.isEmpty() && files.size() < 401);
        for (const QString& f : files) {
            QVERIFY2(!f.startsWith('.'), qPrintable("temporary file left behind: " + f));
            QVERIFY2(probeImage(dir.filePath(f)).ok, qPrintable("incomplete frame under a final name: " + f));
        }
    }

    void stopSignalDiscardsAStill() {
        QTemporaryDir dir;
        QProcess p;
        p.setReadChannel(QProcess::StandardError);
        p.start(QStringLiteral(GLINT_EXECUTABLE),
                {"render", cornell, "--out", dir.filePath("still.exr"), "--size", "16x16", "--spp", "1000000"});
        QVERIFY(p.waitForStarted());
        QByteArray err;
        while (!err.contains("GL_RENDERER") && p.waitForReadyRead(60000)) err += p.readAllStandardError();
        QThread::msleep(300); // into the sample loop
        ::kill(pid_t(p.processId()), SIGINT);
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QCOMPARE(p.exitCode(), 128 + SIGINT);
        QVERIFY2(filesIn(dir.path()).isEmpty(), qPrintable(filesIn(dir.path()).join(' '))); // discarded, no temporary
    }

    void badInputFailsClearly() {
        QTemporaryDir dir;
        const QString pattern = dir.filePath("s_####.exr");
        // Usage errors: exit 2, one line.
        for (const QStringList& args : {
                 QStringList{"render", dolly, "--animation", "--out", dir.filePath("s.exr")},                 // no ####
                 QStringList{"render", dolly, "--animation", "--frames", "5-2", "--out", pattern},           // bad range
                 QStringList{"render", dolly, "--animation", "--frames", "x", "--out", pattern},
                 QStringList{"render", dolly, "--frames", "0-3", "--out", dir.filePath("s.exr")},            // no --animation
                 QStringList{"render", dolly, "--out", pattern},                                             // still with ####
                 QStringList{"render", dolly, "--animation", "--shard", "3/3", "--out", pattern},
                 QStringList{"render", dolly, "--animation", "--time", "1", "--out", pattern},
                 QStringList{"render", dolly, "--animation", "--fps", "0", "--out", pattern},
                 QStringList{"render", dolly, "--animation", "--chunk", "0", "--out", pattern},
                 QStringList{"encode", dir.filePath("s.exr"), dir.filePath("v.mp4")},
                 QStringList{"encode", pattern, dir.filePath("v.avi")},
                 QStringList{"encode", pattern, dir.filePath("v.mp4"), "--codec", "prores"}}) {
            auto r = runGlint(args);
            QVERIFY2(r.exitCode == 2, qPrintable(args.join(' ') + " -> " + QString::number(r.exitCode) + ": " + r.err));
            QVERIFY2(r.err.startsWith("glint: ") && r.err.count('\n') == 1, qPrintable(r.err));
        }
        auto k8s = runGlint({"render", dolly, "--animation", "--frames", "0-1", "--out", pattern}, {"JOB_COMPLETION_INDEX=1"});
        QCOMPARE(k8s.exitCode, 2);
        QVERIFY2(k8s.err.contains("--shards"), qPrintable(k8s.err));

        // Failures: exit 1, naming the file.
        auto still = runGlint(QStringList{"render", cornell, "--animation", "--out", pattern} + tiny);
        QCOMPARE(still.exitCode, 1);
        QVERIFY2(still.err.contains("cornell_box.gltf: ") && still.err.contains("no camera path"), qPrintable(still.err));
        auto unwritable = runGlint(QStringList{"render", dolly, "--animation", "--frames", "0-1", "--out",
                                               "/proc/no-such-dir/s_####.exr"} + tiny);
        QCOMPARE(unwritable.exitCode, 1);
        QVERIFY2(unwritable.err.startsWith("glint: /proc/no-such-dir/s_0000.exr: "), qPrintable(unwritable.err));
        auto noFrames = runGlint({"encode", pattern, dir.filePath("v.mp4")});
        QCOMPARE(noFrames.exitCode, 1);
        QVERIFY(filesIn(dir.path()).isEmpty());
    }

    void fullDiskLeavesNoPartialFrame() {
        QTemporaryDir dir;
        const QString full = dir.filePath("full");
        QVERIFY(QDir(dir.path()).mkdir("full"));
        // A 96 KiB tmpfs fills up within a few 64x64 EXR frames. Without the right to mount, a
        // file-size limit makes writes fail the same way (EFBIG instead of ENOSPC).
        const bool mounted = QProcess::execute("mount", {"-t", "tmpfs", "-o", "size=96k", "tmpfs", full}) == 0;
        const QString command = QString("%1 '%2' render '%3' --animation --frames 0-40 --size 64x64 --spp 1 --out '%4/f_####.exr'")
                                    .arg(mounted ? "exec" : "trap '' XFSZ; ulimit -f 96; exec", GLINT_EXECUTABLE, dolly, full);
        QProcess p;
        p.start("/bin/sh", {"-c", command});
        QVERIFY(p.waitForFinished(120000));
        const QString err = QString::fromUtf8(p.readAllStandardError());
        const QStringList files = filesIn(full);
        bool allComplete = true;
        for (const QString& f : files) allComplete = allComplete && !f.startsWith('.') && probeImage(full + "/" + f).ok;
        if (mounted) QProcess::execute("umount", {full});
        QVERIFY2(p.exitCode() == 1, qPrintable(err));
        QVERIFY2(err.contains("glint: " + full + "/f_00"), qPrintable(err));
        QVERIFY2(allComplete, qPrintable(files.join(' ')));
        QVERIFY(files.size() < 41);
    }

    // A still over an image already there, on a full disk: exit 1 with the file and the reason,
    // and the old image stays (a PNG used to be published empty: OpenImageIO's writer did not
    // see the failed flush).
    void fullDiskKeepsTheOldStill() {
        QTemporaryDir dir;
        const QString full = dir.filePath("full");
        QVERIFY(QDir(dir.path()).mkdir("full"));
        const bool mounted = QProcess::execute("mount", {"-t", "tmpfs", "-o", "size=96k", "tmpfs", full}) == 0;
        for (const QString name : {"still.png", "still.exr"}) {
            {
                QFile old(full + "/" + name);
                QVERIFY(old.open(QIODevice::WriteOnly));
                old.write("an image rendered earlier");
            }
            // On the tmpfs a filler takes every free block; otherwise a small file-size limit.
            const QString fill = mounted ? QString("cat /dev/zero > '%1/filler' 2>/dev/null; ").arg(full) : QString();
            const QString command = QString("%1%2 '%3' render '%4' --size 64x64 --spp 1 --out '%5/%6'")
                                        .arg(fill, mounted ? "exec" : "trap '' XFSZ; ulimit -f 1; exec", GLINT_EXECUTABLE, dolly, full, name);
            QProcess p;
            p.start("/bin/sh", {"-c", command});
            QVERIFY(p.waitForFinished(120000));
            const QString err = QString::fromUtf8(p.readAllStandardError());
            QFile::remove(full + "/filler");
            QVERIFY2(p.exitCode() == 1, qPrintable(err));
            const QString reason = mounted ? "No space left on device" : "File too large";
            QVERIFY2(err.contains("glint: " + full + "/" + name + ": cannot write the image: " + reason), qPrintable(err));
            QCOMPARE(readAll(full + "/" + name), QByteArray("an image rendered earlier"));
            QCOMPARE(filesIn(full), QStringList{name});
            QFile::remove(full + "/" + name);
        }
        if (mounted) QProcess::execute("umount", {full});
    }

    void encodeWritesTaggedReproducibleVideos() {
        QTemporaryDir dir;
        QDir(dir.path()).mkdir("f");
        const QString pattern = dir.filePath("f/shot_####.png");
        // 33x17: odd sizes are padded by one pixel for 4:2:0.
        QCOMPARE(runGlint({"render", dolly, "--animation", "--frames", "0-3", "--size", "33x17", "--spp", "1", "--out", pattern}).exitCode, 0);
        const QString mp4 = dir.filePath("v.mp4"), again = dir.filePath("again.mp4");
        auto e = runGlint({"encode", pattern, mp4});
        QVERIFY2(e.exitCode == 0, qPrintable(e.err));
        const QJsonObject h264 = probeVideo(mp4);
        QCOMPARE(h264["codec_name"].toString(), QString("h264"));
        QCOMPARE(h264["pix_fmt"].toString(), QString("yuv420p"));
        QCOMPARE(h264["width"].toInt(), 34);
        QCOMPARE(h264["height"].toInt(), 18);
        QCOMPARE(h264["nb_read_frames"].toString(), QString("4"));
        QCOMPARE(h264["r_frame_rate"].toString(), QString("24/1"));
        QCOMPARE(h264["color_space"].toString(), QString("bt709"));
        QCOMPARE(h264["color_primaries"].toString(), QString("bt709"));
        QCOMPARE(h264["color_transfer"].toString(), QString("bt709"));
        QCOMPARE(runGlint({"encode", pattern, again}).exitCode, 0);
        QCOMPARE(readAll(mp4), readAll(again)); // fixed thread count: same bytes

        const QString mov = dir.filePath("v.mov"), mkv = dir.filePath("v.mkv");
        QCOMPARE(runGlint({"encode", pattern, mov, "--fps", "30"}).exitCode, 0);
        const QJsonObject prores = probeVideo(mov);
        QCOMPARE(prores["codec_name"].toString(), QString("prores"));
        QCOMPARE(prores["pix_fmt"].toString(), QString("yuv422p10le"));
        QCOMPARE(prores["r_frame_rate"].toString(), QString("30/1"));
        QCOMPARE(runGlint({"encode", pattern, mkv, "--codec", "ffv1"}).exitCode, 0);
        const QJsonObject ffv1 = probeVideo(mkv);
        QCOMPARE(ffv1["codec_name"].toString(), QString("ffv1"));
        QCOMPARE(ffv1["width"].toInt(), 33);
        QCOMPARE(ffv1["nb_read_frames"].toString(), QString("4"));

        // A missing frame in the middle is an error, not a shorter video.
        QVERIFY(QFile::remove(dir.filePath("f/shot_0001.png")));
        auto gap = runGlint({"encode", pattern, dir.filePath("gap.mp4")});
        QCOMPARE(gap.exitCode, 1);
        QVERIFY2(gap.err.contains("frame 1 "), qPrintable(gap.err));
        QVERIFY(!QFile::exists(dir.filePath("gap.mp4")));
        QVERIFY(filesIn(dir.path()).filter(QRegularExpression("^\\.")).isEmpty());
    }

    // A video over one already there, on a full disk and in a read-only folder: exit 1 naming the
    // video and the reason, the old video intact, no partial file left. A full disk is a small
    // tmpfs filled up where the test may mount one, else a file-size limit; a read-only folder is
    // a tmpfs remounted read-only, else a folder without write permission.
    void encodeFailureKeepsTheOldVideo() {
        QTemporaryDir dir;
        QDir(dir.path()).mkdir("f");
        const QString pattern = dir.filePath("f/shot_####.png");
        QCOMPARE(runGlint({"render", dolly, "--animation", "--frames", "0-3", "--size", "64x64", "--spp", "1", "--out", pattern}).exitCode, 0);
        const QByteArray earlier("a video encoded earlier");
        for (const bool readOnly : {false, true}) {
            const QString folder = dir.filePath(readOnly ? "ro" : "full");
            QVERIFY(QDir(dir.path()).mkdir(readOnly ? "ro" : "full"));
            const bool mounted = QProcess::execute("mount", {"-t", "tmpfs", "-o", "size=96k", "tmpfs", folder}) == 0;
            const QString video = folder + "/v.mkv";
            {
                QFile old(video);
                QVERIFY(old.open(QIODevice::WriteOnly));
                old.write(earlier);
            }
            QString prefix = "exec";
            if (readOnly && mounted) QCOMPARE(QProcess::execute("mount", {"-o", "remount,ro", folder}), 0);
            else if (readOnly) QVERIFY(QFile::setPermissions(folder, QFile::ReadOwner | QFile::ExeOwner));
            else if (mounted) prefix = QString("cat /dev/zero > '%1/filler' 2>/dev/null; exec").arg(folder);
            else prefix = "trap '' XFSZ; ulimit -f 1; exec";
            QProcess p;
            p.start("/bin/sh", {"-c", QString("%1 '%2' encode '%3' '%4' --codec ffv1").arg(prefix, GLINT_EXECUTABLE, pattern, video)});
            QVERIFY(p.waitForFinished(120000));
            const QString err = QString::fromUtf8(p.readAllStandardError());
            QFile::remove(folder + "/filler");
            const QStringList left = filesIn(folder);
            const QByteArray kept = readAll(video);
            if (mounted) QProcess::execute("umount", {folder});
            else QFile::setPermissions(folder, QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
            const QString reason = readOnly ? (mounted ? "Read-only file system" : "Permission denied")
                                            : (mounted ? "No space left on device" : "File too large");
            QVERIFY2(p.exitCode() == 1, qPrintable(err));
            QVERIFY2(err.startsWith("glint: " + video + ": ") && err.contains(reason), qPrintable(err));
            QCOMPARE(kept, earlier);
            QCOMPARE(left, QStringList{"v.mkv"});
        }
    }

    void renderWithVideoEncodesExrFrames() {
        QTemporaryDir dir;
        const QString mp4 = dir.filePath("v.mp4");
        auto r = runGlint(QStringList{"render", dolly, "--animation", "--frames", "0-2", "--fps", "12", "--out",
                                      dir.filePath("s_##.exr"), "--video", mp4} + tiny);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject v = probeVideo(mp4);
        QCOMPARE(v["nb_read_frames"].toString(), QString("3"));
        QCOMPARE(v["r_frame_rate"].toString(), QString("12/1")); // from the frames' metadata
        QCOMPARE(v["width"].toInt(), 32);
    }
};

QTEST_GUILESS_MAIN(TestCliOutput)
#include "test_cli_output.moc"
