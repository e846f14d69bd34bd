#pragma once

#include "model/eol/UnitRecord.h"

#include <QCoreApplication>
#include <QFont>
#include <QString>

namespace opentop {

// The operator screen's banner, one table: what each state of the station reads as and its
// colour, so that a state looks the same wherever the screen shows it; and the screen's type
// sizes, read from across the line.
class VerdictLook
{
    Q_DECLARE_TR_FUNCTIONS(opentop::VerdictLook)
public:
    enum class State
    {
        Ready,
        Testing,
        NotStarted,
        Pass,
        Fail,
        StationError,
        Aborted,
        NotRecorded
    };
    static QString text(State state);
    static QString colour(State state); // "#1e7b34"
    static State of(UnitStatus status);
    // What is said under a unit's verdict: the reason, and for a station error that it is none.
    static QString reason(const UnitRecord& record, const QString& reason);
    // `font` enlarged by `factor` for the operator screen.
    static QFont scaled(QFont font, double factor, bool bold = false);
};

} // namespace opentop
