// A real Slurm job array renders an animation in 4 shards and a dependent job encodes it
// (resources/farm/*.sbatch); the frames must be bit-identical to one local run. The test starts
// its own one-node cluster (tests/farm/local_slurm.sh) and fails, loudly, when it cannot.
#include "../cli/cli_runner.h"
#include "../cli/image_probe.h"

#include <QDir>
#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QThread>
#include <QtTest>

namespace {

const QString scene = QStringLiteral(GLINT_RESOURCES_DIR "/farm/cornell_dolly.gltf");
const QString farmScripts = QStringLiteral(GLINT_RESOURCES_DIR "/farm");
const QString clusterScript = QStringLiteral(GLINT_FARM_TEST_DIR "/local_slurm.sh");

struct Run {
    int exitCode = -1;
    QString out;
    QString err;
};

Run run(const QString& program, const QStringList& args, const QProcessEnvironment& env, int timeoutMs = 60000) {
    QProcess p;
    p.setProcessEnvironment(env);
    p.start(program, args);
    Run r;
    if (!p.waitForFinished(timeoutMs)) {
        p.kill();
        p.waitForFinished();
        r.err = program + " timed out";
        return r;
    }
    r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    r.out = QString::fromUtf8(p.readAllStandardOutput()).trimmed();
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

} // namespace

class TestFarm : public QObject {
    Q_OBJECT
    QTemporaryDir work_;
    QProcessEnvironment env_ = QProcessEnvironment::systemEnvironment();
    bool started_ = false;

    QString cluster() const { return work_.filePath("cluster"); }

    // Waits until no job of ours is queued or running; false on timeout.
    bool waitForQueueToEmpty(int timeoutMs) {
        QElapsedTimer timer;
        timer.start();
        while (timer.elapsed() < timeoutMs) {
            const Run q = run("squeue", {"-h", "-o", "%i %T"}, env_);
            if (q.exitCode == 0 && q.out.isEmpty()) return true;
            QThread::msleep(500);
        }
        return false;
    }

private slots:
    void initTestCase() {
        QVERIFY(work_.isValid());
        const Run start = run("/bin/sh", {clusterScript, "start", cluster()}, env_);
        // Loud on purpose: a farm test that cannot start its cluster has tested nothing.
        if (start.exitCode != 0) QFAIL(qPrintable("cannot start the local Slurm cluster:\n" + start.err));
        started_ = true;
        env_.insert("SLURM_CONF", cluster() + "/slurm.conf");
    }

    void cleanupTestCase() {
        if (started_) run("/bin/sh", {clusterScript, "stop", cluster()}, env_);
    }

    void jobArrayFramesMatchOneRunAndEncode() {
        const QString frames = work_.filePath("farm/shot_####.exr");
        const QString video = work_.filePath("shot.mp4");
        QProcessEnvironment job = env_;
        job.insert("GLINT", GLINT_EXECUTABLE);
        job.insert("SCENE", scene);
        job.insert("OUT", frames);
        job.insert("VIDEO", video);
        job.insert("FRAMES", "0-7");
        job.insert("GLINT_ARGS", "--size 32x32 --spp 2");
        job.insert("TASKS", "4");
        const Run submit = run("/bin/bash", {farmScripts + "/submit.sh", "--chdir=" + work_.path()}, job);
        QVERIFY2(submit.exitCode == 0, qPrintable(submit.err));
        QVERIFY2(waitForQueueToEmpty(180000), "the jobs did not finish within 180 s");

        const QStringList logs = QDir(work_.path()).entryList({"glint-*.log"});
        QString logText;
        for (const QString& log : logs) {
            QFile f(work_.filePath(log));
            if (f.open(QIODevice::ReadOnly)) logText += "--- " + log + "\n" + QString::fromUtf8(f.readAll());
        }
        QCOMPARE(logs.filter("glint-render-").size(), 4); // one log per array task
        QVERIFY2(logText.contains("shard 3/4: 2 frames"), qPrintable(logText));
        QVERIFY2(QFile::exists(video), qPrintable("no video; job logs:\n" + logText));

        // The same frames in one local run: bit-identical pixels and AOVs.
        const QString local = work_.filePath("local/shot_####.exr");
        QDir(work_.path()).mkdir("local");
        const auto r = runGlint({"render", scene, "--animation", "--frames", "0-7", "--size", "32x32", "--spp", "2",
                                 "--out", local});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        for (int f = 0; f <= 7; ++f) {
            const QString name = QString("shot_%1.exr").arg(f, 4, 10, QChar('0'));
            const ProbedImage a = probeImage(work_.filePath("farm/" + name)), b = probeImage(work_.filePath("local/" + name));
            QVERIFY2(a.ok && b.ok, qPrintable(name));
            QCOMPARE(a.channels, b.channels);
            QVERIFY2(a.pixels == b.pixels, qPrintable(name + " differs between the farm and one local run"));
        }

        const Run probe = run("ffprobe", {"-v", "error", "-select_streams", "v:0", "-count_frames", "-show_entries",
                                          "stream=codec_name,nb_read_frames,width,height", "-of", "json", video},
                              env_);
        const QJsonObject stream = QJsonDocument::fromJson(probe.out.toUtf8()).object()["streams"].toArray()[0].toObject();
        QCOMPARE(stream["codec_name"].toString(), QString("h264"));
        QCOMPARE(stream["nb_read_frames"].toString(), QString("8"));
        QCOMPARE(stream["width"].toInt(), 32);
    }
};

QTEST_GUILESS_MAIN(TestFarm)
#include "test_farm.moc"
