#pragma once

#include "model/monitor/TrendHistory.h"

#include <QCoreApplication>
#include <QVector>
#include <optional>

namespace opentop {

// The read-out of a trend chart's markers A and B: their times, Δt, and for each series its
// values at A and B with the unit and their difference, so nobody has to read them off a line.
class TrendReadout
{
    Q_DECLARE_TR_FUNCTIONS(opentop::TrendReadout)
public:
    struct Row
    {
        QString name; // "1 DBU200 Current speed"
        QString unit; // "r/min"
        const TrendHistory::Series* series = nullptr;
    };

    static QString text(const QVector<Row>& rows, std::optional<qint64> a, std::optional<qint64> b);
    // "1500 r/min", "-12.5 %": a value as the read-out shows it.
    static QString valueText(double value, const QString& unit, bool sign = false);
    // "12:01:05.250" in local time.
    static QString timeText(qint64 ms);
};

} // namespace opentop
