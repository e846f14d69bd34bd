#include "trends/TrendAxes.h"

#include "trends/TrendPoints.h"

#include <QChart>
#include <QFontMetricsF>
#include <QValueAxis>

namespace opentop {

TrendAxes::TrendAxes(QChart* chart)
    : m_axes{new QValueAxis(chart), new QValueAxis(chart)}
{
    for (QValueAxis* axis : m_axes) {
        axis->setLabelFormat(QStringLiteral("%g"));
        // A value shown as "..." on a short chart could be misread as no value at all.
        axis->setTruncateLabels(false);
        chart->addAxis(axis, axis == m_axes[0] ? Qt::AlignLeft : Qt::AlignRight);
    }
    m_axes[1]->setVisible(false);
    m_axes[1]->setGridLineVisible(false); // its ticks rarely meet the left axis' grid
}

void TrendAxes::setQuantities(const QVector<QPair<QString, QString>>& quantities)
{
    m_units.clear();
    for (const auto& q : quantities) {
        if (!m_units.contains(q.second))
            m_units << q.second;
    }
    QStringList titles;
    QStringList units;
    for (const QString& unit : m_units) {
        QStringList labels;
        for (const auto& q : quantities) {
            if (q.second == unit && !labels.contains(q.first))
                labels << q.first;
        }
        const QString names = labels.join(QStringLiteral(", "));
        titles << (unit.isEmpty() ? names : tr("%1 [%2]").arg(names, unit));
        // Too long for the axis: the word the labels share ("Current speed", "Target speed"
        // -> "Speed [r/min]"), else the unit alone.
        const QString shared = sharedWord(labels);
        units << (unit.isEmpty()     ? names
                  : shared.isEmpty() ? tr("[%1]").arg(unit)
                                     : tr("%1 [%2]").arg(shared, unit));
    }
    m_titles[0] = {titles.value(0), units.value(0)};
    m_titles[1] = {titles.mid(1).join(QStringLiteral(" / ")),
                   units.mid(1).join(QStringLiteral(" / "))};
    m_axes[1]->setVisible(m_units.size() > 1);
    fitTitles(0);
}

QString TrendAxes::sharedWord(const QStringList& labels)
{
    if (labels.size() < 2)
        return QString();
    const QString last = labels.first().section(QLatin1Char(' '), -1);
    for (const QString& l : labels) {
        if (l.section(QLatin1Char(' '), -1).compare(last, Qt::CaseInsensitive) != 0)
            return QString();
    }
    return last.left(1).toUpper() + last.mid(1);
}

void TrendAxes::setRange(int side, double lo, double hi)
{
    TrendPoints::pad(&lo, &hi);
    const int ticks = TrendPoints::niceTicks(&lo, &hi, 6);
    axis(side)->setRange(lo, hi);
    axis(side)->setTickCount(ticks);
}

void TrendAxes::fitTitles(double plotHeight)
{
    for (int i = 0; i < 2; ++i) {
        const QFontMetricsF metrics(m_axes[i]->titleFont());
        const bool fits =
            plotHeight <= 0 || metrics.horizontalAdvance(m_titles[i].first) < plotHeight;
        m_axes[i]->setTitleText(fits ? m_titles[i].first : m_titles[i].second);
    }
}

} // namespace opentop
