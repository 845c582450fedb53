// `glint bench` end to end on the Cornell box at 16x16: the CSV has the columns of docs/CLI.md and
// one row per requested configuration, JSON and both chart files are written, and usage errors
// exit with 2.
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

class TestBenchCommand : public QObject {
    Q_OBJECT

    static int runGlint(const QStringList& arguments, QByteArray* out = nullptr) {
        QProcess process;
        process.start(GLINT_EXECUTABLE, arguments);
        if (!process.waitForFinished(90000)) return -1;
        if (out) *out = process.readAllStandardOutput();
        return process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
    }

private slots:
    void writesTableFilesAndChart() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QByteArray table;
        const QString scene = QString(GLINT_RESOURCES_DIR) + "/scenes/cornell_box/cornell_box.gltf";
        QCOMPARE(runGlint({"bench", scene, "--config", "Full,accumulate", "--frames", "3", "--size", "16x16",
                           "--reference-spp", "8", "--out", dir.path()}, &table), 0);
        QFile csv(dir.filePath("bench.csv"));
        QVERIFY(csv.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = csv.readAll().trimmed().split('\n');
        QCOMPARE(lines.size(), 3);
        QCOMPARE(lines[0], QByteArray("config,spp,bounces,gi,ao,taa,svgf,frames,ms_median,ms_p10,ms_p90,fps,relmse,ssim"));
        QVERIFY(lines[1].startsWith("full,1,"));
        QVERIFY(lines[2].startsWith("accumulate,1,"));
        QCOMPARE(lines[1].split(',').size(), 14);
        for (const char* file : {"bench.json", "speed_accuracy.png", "speed_accuracy.svg"})
            QVERIFY2(QFileInfo(dir.filePath(file)).size() > 100, file);
        QVERIFY(table.contains("TAA/SVGF"));
        QVERIFY(!QFileInfo::exists(dir.filePath("bench_path.csv"))); // no camera path, no path series
    }

    // The Cornell box with a one-second dolly: the camera-path series has the same columns, one row
    // per configuration over the path's frames, and its chart. Tolerance: along the path Full's mean
    // relMSE is below Accumulate's (which restarts every moving frame: raw 1 spp).
    void alongTheCameraPath() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString scene = QString(GLINT_RESOURCES_DIR) + "/farm/cornell_dolly.gltf";
        QCOMPARE(runGlint({"bench", scene, "--config", "full,accumulate", "--frames", "2", "--size", "16x16",
                           "--reference-spp", "8", "--path-frames", "5", "--path-reference-spp", "16", "--out", dir.path()}),
                 0);
        QFile csv(dir.filePath("bench_path.csv"));
        QVERIFY(csv.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = csv.readAll().trimmed().split('\n');
        QCOMPARE(lines.size(), 3);
        QCOMPARE(lines[0], QByteArray("config,spp,bounces,gi,ao,taa,svgf,frames,ms_median,ms_p10,ms_p90,fps,relmse,ssim"));
        const QList<QByteArray> full = lines[1].split(','), accumulate = lines[2].split(',');
        QCOMPARE(full[0], QByteArray("full"));
        QCOMPARE(full[7], QByteArray("5"));
        QVERIFY2(full[12].toDouble() < accumulate[12].toDouble(), (full[12] + " vs " + accumulate[12]).constData());
        for (const char* file : {"bench_path.json", "speed_accuracy_path.png", "speed_accuracy_path.svg"})
            QVERIFY2(QFileInfo(dir.filePath(file)).size() > 100, file);
    }

    void unknownConfigurationIsAUsageError() {
        const QString scene = QString(GLINT_RESOURCES_DIR) + "/scenes/cornell_box/cornell_box.gltf";
        QCOMPARE(runGlint({"bench", scene, "--config", "ultra"}), 2);
    }
};

QTEST_GUILESS_MAIN(TestBenchCommand)
#include "test_bench_command.moc"
