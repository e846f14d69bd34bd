#include "ui/trends/TrendReadout.h"

#include <QDateTime>

namespace opentop {

QString TrendReadout::valueText(double value, const QString& unit, bool sign)
{
    // Seven significant digits: no "1.5e+03" for speeds, no float noise for currents.
    QString number = QString::number(value, 'g', 7);
    if (sign && value > 0)
        number.prepend(QLatin1Char('+'));
    return unit.isEmpty() ? number : QStringLiteral("%1 %2").arg(number, unit);
}

QString TrendReadout::timeText(qint64 ms)
{
    return QDateTime::fromMSecsSinceEpoch(ms).toString(QStringLiteral("hh:mm:ss.zzz"));
}

QString TrendReadout::text(const QVector<Row>& rows, std::optional<qint64> a,
                           std::optional<qint64> b)
{
    if (!a && !b)
        return tr("Markers: click in the chart to set marker A, click again to set marker B.");
    QStringList lines;
    if (a && b) {
        lines << tr("A %1   B %2   Δt = B − A = %3 s")
                     .arg(timeText(*a), timeText(*b), QString::number((*b - *a) / 1000.0, 'f', 3));
    } else {
        lines << (a ? tr("A %1   (click in the chart to set marker B)").arg(timeText(*a))
                    : tr("B %1   (click in the chart to set marker A)").arg(timeText(*b)));
    }
    const QString none = tr("no data");
    for (const Row& row : rows) {
        double va = 0;
        double vb = 0;
        const bool hasA = a && row.series && TrendHistory::valueAt(*row.series, *a, &va);
        const bool hasB = b && row.series && TrendHistory::valueAt(*row.series, *b, &vb);
        const QString textA = hasA ? valueText(va, row.unit) : none;
        const QString textB = hasB ? valueText(vb, row.unit) : none;
        if (a && b) {
            const QString delta = hasA && hasB ? valueText(vb - va, row.unit, true) : none;
            lines << tr("%1:   A %2   B %3   Δ %4").arg(row.name, textA, textB, delta);
        } else {
            lines << tr("%1:   %2 %3")
                         .arg(row.name, a ? QStringLiteral("A") : QStringLiteral("B"),
                              a ? textA : textB);
        }
    }
    return lines.join(QLatin1Char('\n'));
}

} // namespace opentop
