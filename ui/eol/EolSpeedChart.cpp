#include "ui/eol/EolSpeedChart.h"

#include <QChart>
#include <QChartView>
#include <QLineSeries>
#include <QVBoxLayout>
#include <QValueAxis>
#include <algorithm>
#include <cmath>

namespace opentop {

EolSpeedChart::EolSpeedChart(QWidget* parent)
    : QWidget(parent)
    , m_chart(new QChart)
    , m_time(new QValueAxis(m_chart))
    , m_speed(new QValueAxis(m_chart))
{
    m_chart->legend()->setAlignment(Qt::AlignRight);
    m_time->setTitleText(tr("time (s)"));
    m_time->setLabelFormat(QStringLiteral("%.0f"));
    m_time->setTickCount(6); // 0, 2, 4, ... of whole tens of seconds: labels stay whole numbers
    m_speed->setLabelFormat(QStringLiteral("%.0f"));
    m_chart->addAxis(m_time, Qt::AlignBottom);
    m_chart->addAxis(m_speed, Qt::AlignLeft);
    m_chart->setMargins(QMargins(4, 4, 4, 4));
    m_view = new QChartView(m_chart, this);
    m_view->setRenderHint(QPainter::Antialiasing);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_view);
    clear();
}

void EolSpeedChart::clear()
{
    m_chart->removeAllSeries();
    m_series.clear();
    m_maxSpeed = 0;
    m_time->setRange(0, 10);
    m_speed->setRange(0, 100);
    // Numbers without a unit are not shown: the unit is known from the first sample on.
    m_speed->setLabelsVisible(!m_unit.isEmpty());
    m_speed->setTitleText(m_unit.isEmpty() ? tr("speed") : tr("speed (%1)").arg(m_unit));
}

void EolSpeedChart::add(int machineNumber, double seconds, double speed, const QString& unit)
{
    QLineSeries*& series = m_series[machineNumber];
    if (!series) {
        series = new QLineSeries(m_chart);
        series->setName(tr("drive %1").arg(machineNumber));
        m_chart->addSeries(series);
        series->attachAxis(m_time);
        series->attachAxis(m_speed);
        m_unit = unit;
        m_speed->setTitleText(tr("speed (%1)").arg(unit));
        m_speed->setLabelsVisible(true);
    }
    series->append(seconds, speed);
    m_maxSpeed = std::max(m_maxSpeed, std::abs(speed));
    // Whole tens of seconds, and a speed axis with room above the fastest drive.
    m_time->setRange(0, std::max(10.0, std::ceil(seconds / 10.0) * 10.0));
    m_speed->setRange(std::min(0.0, speed < 0 ? -m_maxSpeed * 1.1 : 0.0),
                      std::max(100.0, m_maxSpeed * 1.1));
    m_speed->applyNiceNumbers();
}

int EolSpeedChart::pointCount() const
{
    int n = 0;
    for (const QLineSeries* s : m_series)
        n += s->count();
    return n;
}

} // namespace opentop
