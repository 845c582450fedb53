#include "speed_accuracy_chart.h"

#include <QtCharts/QChart>
#include <QtCharts/QLegend>
#include <QtCharts/QLineSeries>
#include <QtCharts/QLogValueAxis>
#include <QCoreApplication>
#include <QGraphicsScene>
#include <QImage>
#include <QPainter>
#include <QSvgGenerator>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace glint::bench {
namespace {

constexpr int chartWidth = 900;
constexpr int chartHeight = 600;

// Qt labels a log axis only at the powers of its base inside the range: a range within one decade
// or two (0.02 to 0.3) got the single label "0.1". The range is widened to whole decades, so every
// decade it spans is labelled, both ends included, with the 2..9 minor ticks between.
QLogValueAxis* logAxis(const QString& title, double low, double high) {
    auto* axis = new QLogValueAxis;
    axis->setTitleText(title);
    axis->setBase(10.0);
    axis->setLabelFormat("%g");
    axis->setMinorTickCount(8);
    const double first = std::pow(10.0, std::floor(std::log10(low) + 1e-9));
    double last = std::pow(10.0, std::ceil(std::log10(high) - 1e-9));
    if (last <= first) last = first * 10.0;
    axis->setRange(first * (1.0 - 1e-6), last * (1.0 + 1e-6)); // Qt drops an end label that rounds outside
    return axis;
}

// The chart owns its series and axes.
QChart* buildChart(const std::vector<ChartCurve>& curves, const std::string& title) {
    auto* chart = new QChart;
    chart->setTitle(QString::fromStdString(title));
    chart->setAnimationOptions(QChart::NoAnimation);
    double minMs = std::numeric_limits<double>::max(), maxMs = 0.0;
    double minErr = std::numeric_limits<double>::max(), maxErr = 0.0;
    for (const ChartCurve& curve : curves) {
        auto* line = new QLineSeries;
        line->setName(QString::fromStdString(curve.name));
        for (const ChartPoint& p : curve.points) {
            if (p.ms <= 0.0 || p.relmse <= 0.0) continue; // log axes
            line->append(p.ms, p.relmse);
            minMs = std::min(minMs, p.ms);
            maxMs = std::max(maxMs, p.ms);
            minErr = std::min(minErr, p.relmse);
            maxErr = std::max(maxErr, p.relmse);
        }
        chart->addSeries(line);
    }
    if (maxMs <= 0.0) minMs = 1.0, maxMs = 10.0, minErr = 1e-3, maxErr = 1.0;
    QLogValueAxis* x = logAxis("time (ms, cumulative)", minMs / 1.5, maxMs * 1.5);
    QLogValueAxis* y = logAxis("relMSE against the reference", minErr / 1.5, maxErr * 1.5);
    chart->addAxis(x, Qt::AlignBottom);
    chart->addAxis(y, Qt::AlignLeft);
    for (QAbstractSeries* s : chart->series()) {
        s->attachAxis(x);
        s->attachAxis(y);
    }
    chart->legend()->setAlignment(Qt::AlignRight);
    return chart;
}

} // namespace

void writeSpeedAccuracyChart(const std::vector<ChartCurve>& curves, const std::string& title,
                             const std::string& pngPath, const std::string& svgPath) {
    // A scene without a view: the chart is laid out at its fixed size and rendered twice.
    QGraphicsScene scene;
    QChart* chart = buildChart(curves, title);
    scene.addItem(chart); // the scene owns the chart
    chart->setGeometry(0, 0, chartWidth, chartHeight);
    chart->setBackgroundRoundness(0);
    QCoreApplication::processEvents(); // lets the chart lay out its axes and legend
    const QRectF area(0, 0, chartWidth, chartHeight);
    QImage image(chartWidth, chartHeight, QImage::Format_ARGB32);
    image.fill(Qt::white);
    {
        QPainter painter(&image);
        painter.setRenderHint(QPainter::Antialiasing);
        scene.render(&painter, area, area);
    }
    if (!image.save(QString::fromStdString(pngPath), "PNG")) throw std::runtime_error("cannot write " + pngPath);

    QSvgGenerator svg;
    svg.setFileName(QString::fromStdString(svgPath));
    svg.setSize(QSize(chartWidth, chartHeight));
    svg.setViewBox(QRect(0, 0, chartWidth, chartHeight));
    svg.setTitle(QString::fromStdString(title));
    {
        QPainter painter;
        if (!painter.begin(&svg)) throw std::runtime_error("cannot write " + svgPath);
        scene.render(&painter, area, area);
    }
}

} // namespace glint::bench
