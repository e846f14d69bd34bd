#include "model/monitor/TrendCsv.h"

#include "model/io/DisplayText.h"
#include "model/io/OutputFile.h"

#include <QDateTime>
#include <limits>

namespace opentop {

namespace {

// A header cell names a drive: made safe for a spreadsheet (DisplayText::csvCell), then quoted.
QString quoted(const QString& cell)
{
    QString text = DisplayText::csvCell(cell);
    if (!text.contains(QLatin1Char(',')) && !text.contains(QLatin1Char('"')))
        return text;
    return QLatin1Char('"') + text.replace(QLatin1Char('"'), QStringLiteral("\"\"")) +
           QLatin1Char('"');
}

} // namespace

QByteArray TrendCsv::toCsv(const QVector<Column>& columns, qint64 fromMs, qint64 toMs)
{
    const bool all = toMs < fromMs;
    QStringList header{tr("time"), tr("seconds")};
    QVector<int> next(columns.size(), 0); // per column: the next point to write
    for (int c = 0; c < columns.size(); ++c) {
        const TrendHistory::Series& s = *columns[c].series;
        header << quoted(
            s.unit.isEmpty()
                ? QStringLiteral("%1 %2").arg(columns[c].source, s.label)
                : QStringLiteral("%1 %2 [%3]").arg(columns[c].source, s.label, s.unit));
        next[c] = all ? 0 : TrendHistory::lowerBound(s, fromMs);
    }
    QByteArray out = header.join(QLatin1Char(',')).toUtf8() + '\n';
    qint64 first = -1;
    // Merge the series by time: each row is the earliest instant not yet written.
    for (;;) {
        qint64 t = std::numeric_limits<qint64>::max();
        for (int c = 0; c < columns.size(); ++c) {
            const auto& points = columns[c].series->points;
            if (next[c] < points.size() && (all || points[next[c]].ms <= toMs))
                t = std::min(t, points[next[c]].ms);
        }
        if (t == std::numeric_limits<qint64>::max())
            break;
        if (first < 0)
            first = t;
        QStringList row{QDateTime::fromMSecsSinceEpoch(t).toString(Qt::ISODateWithMs),
                        QString::number((t - first) / 1000.0, 'f', 3)};
        for (int c = 0; c < columns.size(); ++c) {
            const auto& points = columns[c].series->points;
            if (next[c] < points.size() && points[next[c]].ms == t)
                row << QString::number(points[next[c]++].value, 'g', 10);
            else
                row << QString();
        }
        out += row.join(QLatin1Char(',')).toUtf8() + '\n';
    }
    return out;
}

bool TrendCsv::write(const QString& path, const QVector<Column>& columns, qint64 fromMs,
                     qint64 toMs, QString* error)
{
    // Replaced atomically when a regular file; a device or FIFO written through, every write
    // error reported; a directory refused.
    return OutputFile::write(path, toCsv(columns, fromMs, toMs), error);
}

} // namespace opentop
