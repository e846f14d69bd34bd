#include "ui/eol/StationNotice.h"

#include "model/io/DisplayText.h"
#include "model/station/EolStation.h"

#include <QDateTime>

namespace opentop {

StationNotice::StationNotice(EolStation* station, QWidget* parent)
    : QLabel(parent)
    , m_station(station)
{
    setObjectName(QStringLiteral("stationNotice"));
    setWordWrap(true);
    setTextFormat(Qt::PlainText); // serials, database errors, recipe names
    setStyleSheet(QStringLiteral(
        "QLabel { background: #ffe08a; color: black; padding: 4px; border-radius: 4px; }"));
    hide();
    connect(m_station, &EolStation::resultsWaitingChanged, this, [this] { refresh(); });
    connect(m_station, &EolStation::interruptedFound, this, [this] { refresh(); });
    connect(m_station, &EolStation::safetyChanged, this, [this] { refresh(); });
    refresh();
}

void StationNotice::refresh()
{
    QStringList lines;
    const int waiting = m_station->resultsWaiting();
    if (waiting > 0)
        lines << tr("%n result(s) kept on this station, not yet in the results database: %1. "
                    "They are sent by themselves, in order, when it answers.",
                    nullptr, waiting)
                     .arg(m_station->resultsWaitingError().isEmpty()
                              ? tr("it does not answer")
                              : m_station->resultsWaitingError());
    for (const StationLease::Leftover& unit : m_station->interruptedUnits())
        lines << tr("Unit %1 (begun %2) was not finished: the station stopped during its test. "
                    "It is recorded as interrupted; test it again.")
                     .arg(unit.serial, QDateTime::fromString(unit.started, Qt::ISODateWithMs)
                                           .toLocalTime()
                                           .toString(QStringLiteral("yyyy-MM-dd HH:mm:ss")));
    if (m_station->isMakingSafe())
        lines << tr("Making the recipe's drives safe: reading each, stopping one left running, "
                    "giving control back to their inputs…");
    else
        for (const PositionSafety& p : m_station->safety())
            if (p.worthSaying())
                lines << p.summary();
    // Serials and errors from the database, names from the recipe: escaped, line by line.
    setText(DisplayText::escapedLines(lines.join(QLatin1Char('\n'))));
    setVisible(!lines.isEmpty());
}

} // namespace opentop
