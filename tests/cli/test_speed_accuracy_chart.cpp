// The speed-vs-accuracy chart of `glint bench`: its log axes label every decade they span (with
// errors between 0.02 and 0.3 the relMSE axis had the single label "0.1").
#include "app/bench/speed_accuracy_chart.h"

#include <QApplication>
#include <QFile>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

class TestSpeedAccuracyChart : public QObject {
    Q_OBJECT
private slots:
    void logAxesLabelEveryDecade() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const std::vector<glint::bench::ChartCurve> curves{
            {"Accumulate", {{3.0, 0.3}, {12.0, 0.09}, {40.0, 0.02}}},
            {"Full", {{5.0, 0.12}, {25.0, 0.05}}}};
        const QString svg = dir.filePath("chart.svg");
        glint::bench::writeSpeedAccuracyChart(curves, "test", dir.filePath("chart.png").toStdString(), svg.toStdString());
        QFile file(svg);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(file.readAll());
        QStringList labels; // the text items of the SVG
        const QRegularExpression item(QStringLiteral(">\\s*([0-9.e+-]+)\\s*</text>"));
        for (auto it = item.globalMatch(text); it.hasNext();) labels << it.next().captured(1);
        // relMSE 0.02 .. 0.3: 0.01, 0.1 and 1; time 3 .. 40 ms: 1, 10 and 100.
        for (const char* decade : {"0.01", "0.1", "1", "10", "100"})
            QVERIFY2(labels.contains(decade), qPrintable(QString("%1 missing from %2").arg(decade, labels.join(' '))));
    }
};

int main(int argc, char** argv) {
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    TestSpeedAccuracyChart test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_speed_accuracy_chart.moc"
