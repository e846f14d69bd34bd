#pragma once

#include "tests/faultmatrix/BackupValues.h"
#include "tests/faultmatrix/FaultCounts.h"
#include "tests/faultmatrix/MatrixCli.h"

#include <QHash>

namespace opentop::faultmatrix {

// The drives' true registers per MatrixSim::key(slave, name).
using Truth = QHash<QString, QVector<quint16>>;

// The counting rules: what the tool told the user (exit code, messages, report) against what
// the drives really hold. Pure functions, so that they can be tested on made-up reports.
class FaultJudge
{
public:
    // A backup that exited 0: every value in the file against the drive; every drive asked
    // for is in the file, and the user was told the file was written.
    static void backupDone(const QVector<Setting>& file, const Truth& truth,
                           const QVector<int>& asked, const QString& path, const CliRun& run,
                           FaultCounts* counts);
    // A backup that did not exit 0: it gave up, must say why, and must leave the file alone.
    static void backupFailed(const CliRun& run, bool fileTouched, FaultCounts* counts);
    // A restore (opentop-cli --json restore FILE --yes) and the drives afterwards.
    static void restore(const QVector<Setting>& file, const Truth& after, const CliRun& run,
                        FaultCounts* counts);
    // A restore that wrote a setting the drive already held (`before`, the truth before the
    // run) because it read another value: it misread the drive (issue 28: late replies taken
    // for answers). A setting read as equal and written with its block is no misread.
    static void needlessWrites(const QVector<Setting>& file, const Truth& before, const CliRun& run,
                               FaultCounts* counts);
    // At the end: every drive equal to the file.
    static void finalState(const QVector<Setting>& file, const Truth& truth, FaultCounts* counts);
    // opentop-cli --json compare FILE:ID ID for one drive.
    static void compare(const QVector<Setting>& fileOfSlave, const Truth& truth, int slave,
                        const CliRun& run, FaultCounts* counts);

    static bool documentedExit(int code);
};

} // namespace opentop::faultmatrix
