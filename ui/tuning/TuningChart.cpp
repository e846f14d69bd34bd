#include "ui/tuning/TuningChart.h"

#include <QChart>
#include <QFontMetricsF>
#include <QLineSeries>
#include <QValueAxis>

#include <algorithm>
#include <cmath>

namespace opentop {

namespace {

constexpr double kBeforeStepMs = 200; // of the approach before the step, shown

double niceCeiling(double v)
{
    if (v <= 0)
        return 1;
    const double magnitude = std::pow(10.0, std::floor(std::log10(v)));
    for (double m : {1.0, 2.0, 2.5, 5.0, 10.0}) {
        if (m * magnitude >= v)
            return m * magnitude;
    }
    return 10 * magnitude;
}

} // namespace

TuningChart::TuningChart(QWidget* parent)
    : QChartView(parent)
    , m_time(new QValueAxis)
    , m_speed(new QValueAxis)
    , m_current(new QValueAxis)
{
    setObjectName(QStringLiteral("tuningChart"));
    auto* chart = new QChart;
    chart->legend()->hide();
    chart->setMargins(QMargins(4, 4, 4, 4));
    m_time->setTitleText(tr("Time (ms)"));
    m_time->setLabelFormat(QStringLiteral("%.0f"));
    m_time->setTickType(QValueAxis::TicksDynamic); // round times from the step on
    m_time->setTickAnchor(0);
    m_current->setTitleText(tr("Current (A)"));
    m_current->setLabelFormat(QStringLiteral("%.1f"));
    m_speed->setLabelFormat(QStringLiteral("%.0f"));
    chart->addAxis(m_time, Qt::AlignBottom);
    chart->addAxis(m_speed, Qt::AlignLeft);
    chart->addAxis(m_current, Qt::AlignRight);
    m_time->setRange(0, 1500);
    m_speed->setRange(0, 100);
    m_current->setRange(0, 1);
    // QChartView made a chart of its own and only releases it (Qt: "To avoid memory leaks
    // users need to make sure the previous chart is deleted"): LeakSanitizer found it.
    QChart* unused = this->chart();
    setChart(chart);
    delete unused;
    setRenderHint(QPainter::Antialiasing);
    setMinimumSize(360, 130);
    setSpeedUnit(QString());
    connect(chart, &QChart::plotAreaChanged, this, &TuningChart::fitTitles);
}

void TuningChart::setSpeedUnit(const QString& unit)
{
    m_speedUnit = unit;
    fitTitles();
}

void TuningChart::fitTitles()
{
    const double room = chart()->plotArea().height();
    const auto show = [room](QValueAxis* axis, const QString& full, const QString& unit) {
        const QString title =
            room <= 0 || QFontMetricsF(axis->titleFont()).horizontalAdvance(full) < room ? full
                                                                                         : unit;
        if (axis->titleText() != title) // a new title lays the chart out again
            axis->setTitleText(title);
    };
    show(m_speed, m_speedUnit.isEmpty() ? tr("Speed") : tr("Speed (%1)").arg(m_speedUnit),
         m_speedUnit.isEmpty() ? QString() : tr("(%1)").arg(m_speedUnit));
    show(m_current, tr("Current (A)"), tr("(%1)").arg(QStringLiteral("A")));
}

int TuningChart::curveCount() const
{
    return int(chart()->series().size());
}

void TuningChart::setRuns(const QVector<const TuningRun*>& runs)
{
    QChart* c = chart();
    c->removeAllSeries();
    double maxT = 0, maxSpeed = 0, minCurrent = 0, maxCurrent = 0;
    const auto add = [&](QLineSeries* s, QValueAxis* y) {
        c->addSeries(s);
        s->attachAxis(m_time);
        s->attachAxis(y);
    };
    for (const TuningRun* run : runs) {
        auto* speed = new QLineSeries;
        auto* command = run->isPrediction() ? nullptr : new QLineSeries;
        auto* current = run->isPrediction() ? nullptr : new QLineSeries;
        for (const TuningSample& s : run->result.samples) {
            if (s.tMs < -kBeforeStepMs)
                continue;
            speed->append(s.tMs, s.speed);
            if (command)
                command->append(s.tMs, s.command);
            if (current)
                current->append(s.tMs, s.current);
            maxT = std::max(maxT, s.tMs);
            maxSpeed = std::max({maxSpeed, s.speed, s.command});
            if (current) {
                minCurrent = std::min(minCurrent, s.current);
                maxCurrent = std::max(maxCurrent, s.current);
            }
        }
        QPen pen(run->color, 2);
        pen.setStyle(run->isPrediction() ? Qt::DashLine : Qt::SolidLine);
        speed->setPen(pen);
        speed->setName(run->title);
        add(speed, m_speed);
        if (command) {
            QPen p(run->color, 1, Qt::DotLine);
            command->setPen(p);
            add(command, m_speed);
        }
        if (current) {
            QPen p(run->color.lighter(130), 1, Qt::DashDotLine);
            current->setPen(p);
            add(current, m_current);
        }
    }
    const double end = niceCeiling(std::max(maxT, 100.0));
    m_time->setRange(runs.isEmpty() ? 0 : -kBeforeStepMs, end);
    m_time->setTickInterval(niceCeiling(end / 6));
    m_speed->setRange(0, niceCeiling(std::max(maxSpeed * 1.1, 10.0)));
    m_current->setRange(minCurrent < 0 ? -niceCeiling(-minCurrent * 1.1) : 0,
                        niceCeiling(std::max(maxCurrent * 1.1, 0.5)));
}

} // namespace opentop
