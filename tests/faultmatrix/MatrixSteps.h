#pragma once

#include "tests/faultmatrix/BackupValues.h"
#include "tests/faultmatrix/FaultCounts.h"
#include "tests/faultmatrix/FaultJudge.h"
#include "tests/faultmatrix/MatrixCli.h"
#include "tests/faultmatrix/MatrixOptions.h"
#include "tests/faultmatrix/MatrixSim.h"

#include <QTemporaryDir>
#include <QTextStream>
#include <functional>
#include <random>

namespace opentop::faultmatrix {

// One seed's bus (an opentop-sim process on a pty symlink) and the steps a user takes on it:
// back up, change settings on the drives, restore, compare. Each step judges what the tool
// reported against the drives' true registers and adds to the seed's counts.
class MatrixSteps
{
public:
    MatrixSteps(const MatrixOptions& options, int seed, QTextStream& log);

    bool start(QString* error);
    // Runs the whole seed: backup, change, restore, compare.
    FaultCounts runSeed();

    // backup 1-N -o FILE, repeated while it gives up (up to the options' attempts).
    bool backup();
    // Changes 1..4 settings per drive through the simulator's console; returns how many.
    int changeSettings();
    // restore FILE --yes, repeated while it gives up; the last one leaves the drives equal.
    bool restore();
    // compare FILE:ID ID for every drive.
    bool compare();
    // After the restore: changes one restored setting behind the tool's back (--sabotage).
    void sabotage();

    Truth truth();
    QVector<int> slaves() const;
    QString slaveList() const;

    MatrixSim& sim() { return m_sim; }
    const MatrixCli& cli() const { return m_cli; }
    FaultCounts& counts() { return m_counts; }
    const QString& file() const { return m_file; }
    const QVector<Setting>& backupSettings() const { return m_backup; }
    void note(const QString& text);
    // Records an opentop-cli run (count, time, and its output with --verbose).
    void ran(const CliRun& run);
    // A step that could not finish in the options' attempts: the seed proves nothing more.
    void abandon(const QString& step);

private:
    const MatrixOptions& m_options;
    int m_seed;
    QTextStream& m_log;
    QTemporaryDir m_dir;
    QString m_link;
    QString m_file;
    MatrixSim m_sim;
    MatrixCli m_cli;
    FaultCounts m_counts;
    QVector<Setting> m_backup;
    std::mt19937 m_random;
};

} // namespace opentop::faultmatrix
