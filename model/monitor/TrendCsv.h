#pragma once

#include "model/monitor/TrendHistory.h"

#include <QCoreApplication>
#include <QVector>

class QIODevice;

namespace opentop {

// Trend data as CSV for a spreadsheet: one row per sampling instant, a time column in ISO 8601
// local time with milliseconds, seconds since the first row, and one column per series headed
// "<drive> <label> [<unit>]". A series without a sample at an instant has an empty cell (drives
// are polled one after another, so their instants differ).
class TrendCsv
{
    Q_DECLARE_TR_FUNCTIONS(opentop::TrendCsv)
public:
    struct Column
    {
        QString source; // "drive 1"
        const TrendHistory::Series* series = nullptr;
    };

    // Rows with fromMs <= time <= toMs; toMs < fromMs means all.
    static QByteArray toCsv(const QVector<Column>& columns, qint64 fromMs = 0, qint64 toMs = -1);
    static bool write(const QString& path, const QVector<Column>& columns, qint64 fromMs,
                      qint64 toMs, QString* error);
};

} // namespace opentop
