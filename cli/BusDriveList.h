#pragma once

#include <QCoreApplication>
#include <QDateTime>
#include <QString>
#include <QVector>

namespace opentop {

// The drives on the bus as far as the command line knows them, for the group check before a
// write or command (children never reply, so they cannot be found by asking the target):
// --bus-drives LIST, else OPENTOP_BUS_DRIVES, else the simulated bus's list, else the drives the
// last scan of this connection found (BusMemory, shared with the window's scans), said with its
// age. None known: a write to a drive that can be a group parent is refused unless
// --no-group-check.
struct BusDriveList
{
    Q_DECLARE_TR_FUNCTIONS(opentop::BusDriveList)
public:
    enum class Source
    {
        Option,
        Environment,
        Simulated,
        Remembered,
        None
    };
    Source source = Source::None;
    QVector<int> slaves;
    QDateTime savedAt; // Remembered: when the scan saved them (UTC)
    QString place;     // Remembered: the connection as the user knows it

    // Where the list came from, for a note before the group check: "--bus-drives",
    // "the drives the last scan of /dev/ttyUSB0 found (2026-11-29 05:40, 12 min ago)".
    QString sourceText(const QDateTime& now = QDateTime::currentDateTimeUtc()) const;
    // "12 min ago", "3 h ago", "2 days ago".
    static QString ageText(const QDateTime& then, const QDateTime& now);
};

} // namespace opentop
