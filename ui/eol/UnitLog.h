#pragma once

#include "model/eol/UnitRecord.h"

#include <QTableWidget>

namespace opentop {

// The operator screen's log of the last units tested here, newest first (50 at most): the time,
// serial, verdict and reason, the verdict saying when its result is not in the results
// database (not recorded, or kept on this station until the server answers).
class UnitLog : public QTableWidget
{
    Q_OBJECT
public:
    // Where a unit's result is.
    enum class Kept
    {
        Recorded,
        NotRecorded,
        OnStation
    };

    explicit UnitLog(QWidget* parent = nullptr);
    void add(const UnitRecord& record, Kept kept);
    // The newest unit's result is recorded now: its verdict alone.
    void markRecorded(UnitStatus status);
};

} // namespace opentop
