#include "ui/trends/TrendAxes.h"

#include "ui/trends/TrendPoints.h"

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
    // Per side, from the longest title to the shortest (see m_titles); the right-hand side
    // joins the units after the first.
    std::array<QList<QStringList>, 2> sides;
    for (int u = 0; u < m_units.size(); ++u) {
        const QString& unit = m_units[u];
        QStringList labels;
        for (const auto& q : quantities) {
            if (q.second == unit && !labels.contains(q.first))
                labels << q.first;
        }
        const QString names = labels.join(QStringLiteral(", "));
        if (unit.isEmpty()) {
            sides[u == 0 ? 0 : 1] << QStringList{names, names, names, names};
            continue;
        }
        // Too long for the axis: the word the labels share ("Current speed", "Target speed"
        // -> "Speed [r/min]"), then the unit alone.
        const QString shared = sharedWord(labels);
        const QString bare = tr("[%1]").arg(unit);
        sides[u == 0 ? 0 : 1] << QStringList{
            tr("%1 [%2]").arg(names, unit),
            shared.isEmpty() ? bare : tr("%1 [%2]").arg(shared, unit), bare, unit};
    }
    for (int side = 0; side < 2; ++side) {
        m_titles[side] = QStringList{QString(), QString(), QString(), QString()};
        for (int level = 0; level < 4; ++level) {
            QStringList parts;
            for (const QStringList& t : sides[side])
                parts << t[level];
            // The last, shortest: the units alone, without brackets or spaces ("%/A").
            m_titles[side][level] =
                parts.join(level == 3 ? QStringLiteral("/") : QStringLiteral(" / "));
        }
    }
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
        if (m_titles[i].isEmpty())
            continue; // no quantities yet (a layout restored before any was chosen)
        const QFontMetricsF metrics(m_axes[i]->titleFont());
        QString title = m_titles[i].last();
        for (const QString& candidate : std::as_const(m_titles[i])) {
            if (plotHeight <= 0 || metrics.horizontalAdvance(candidate) < plotHeight) {
                title = candidate;
                break;
            }
        }
        m_axes[i]->setTitleText(title);
    }
}

} // namespace opentop
