#pragma once

#include <QString>
#include <QStringList>
#include <QTextStream>

namespace opentop::faultmatrix {

// The matrix's counts for one seed (or their total). The first four must be 0.
struct FaultCounts
{
    QString label;             // "seed 3", "total"
    int backupValues = 0;      // values in backup files compared with the drives
    int backupDiffer = 0;      // values in a backup file that differ from the drive   (must be 0)
    int settingsChanged = 0;   // settings changed behind the tool's back before the restore
    int notVerified = 0;       // settings reported written/unchanged the drive does not hold (0)
    int wrongAfterRestore = 0; // settings not equal to the backup after the last restore (0)
    int unreported = 0;        // wrong or failed, but exit 0 or not named to the user   (must be 0)
    int falseDifferences = 0;  // differences compare reported that do not exist        (must be 0)
    int needlessWrites = 0;    // settings a restore wrote that the drive already held  (must be 0)
    int gaveUp = 0;            // operations that gave up (allowed; each with its reason)
    int operations = 0;        // opentop-cli runs
    qint64 ms = 0;
    QStringList gaveUpReasons;
    QStringList findings; // every must-be-0 count's cases, for people

    bool clean() const;
    // Values the tool read and took that the drive did not hold: in a backup file, or reported
    // verified or unchanged by a restore.
    int misreads() const { return backupDiffer + notVerified; }
    void add(const FaultCounts& other);

    static void printHeader(QTextStream& out);
    void printRow(QTextStream& out) const;
};

} // namespace opentop::faultmatrix
