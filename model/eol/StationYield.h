#pragma once

#include "model/eol/ShiftPlan.h"
#include "model/eol/YieldReport.h"

#include <QDateTime>
#include <QObject>

namespace opentop {

class ResultWriter;

// The figures a station's screen shows: this station's units of this recipe version in this
// shift, read back from the results database and computed by YieldReport, so that the screen
// says what `eol results --yield` says (commandLine() is that command). Queried on the
// writer's thread; the screen keeps the last answer and its time.
class StationYield : public QObject
{
    Q_OBJECT
public:
    explicit StationYield(ResultWriter* writer, QObject* parent = nullptr);

    // Asks again (after a recorded unit, a new recipe, the database opening), for the shift
    // of Settings "eol/shifts" (default 06:00, 14:00, 22:00) that is on now.
    void refresh(const QString& station, const QString& checksum);

    bool known() const { return m_known; }
    const YieldRow& row() const { return m_row; }
    QDateTime shiftStart() const { return m_since; } // UTC
    QDateTime readAt() const { return m_readAt; }
    QString error() const { return m_error; } // why the last query failed
    // The command that prints the same figures.
    QString commandLine() const;

signals:
    void changed();

private:
    ResultWriter* m_writer;
    ShiftPlan m_plan;
    QString m_station;
    QString m_checksum;
    QDateTime m_since;
    QDateTime m_readAt;
    YieldRow m_row;
    bool m_known = false;
    QString m_error;
    quint64 m_generation = 0;
};

} // namespace opentop
