#pragma once

#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <functional>

namespace opentop::faultmatrix {

// What one opentop-cli run gave the user.
struct CliRun
{
    QStringList arguments;
    int code = -1; // -1: crashed, killed or timed out
    QString out;
    QString err;
    qint64 ms = 0;

    QJsonObject json() const; // the --json document on stdout ({} when there is none)
    // The lines a user reads as the reason of a failure ("error: …").
    QString reason() const;
};

// Runs opentop-cli as a user would: the port, the DBU variants, the command. The CLI's own
// defaults for timeout and retries are kept (those are what the matrix proves).
class MatrixCli
{
public:
    // `busDrives`: the drives on the simulated bus (--bus-drives): a restore names the drives
    // each write reaches.
    MatrixCli(const QString& binDir, const QString& port, const QString& variants,
              const QString& busDrives, int baud = 19200);

    CliRun run(const QStringList& command, int timeoutMs = 600000) const;
    // Every run with --trace (MatrixOptions::traceDir).
    void setTrace(bool on) { m_trace = on; }
    // Runs with --trace and calls `onTrace` with the trace so far until it returns true once
    // (e.g. to pull the port out after the third write); the run then goes on to its end.
    CliRun runWatching(const QStringList& command,
                       const std::function<bool(const QString& trace)>& onTrace,
                       int timeoutMs = 600000) const;

    static QString describe(const CliRun& run);

private:
    QStringList arguments(const QStringList& command) const;

    QString m_binDir;
    QString m_port;
    QString m_variants;
    QString m_busDrives;
    int m_baud;
    bool m_trace = false;
};

} // namespace opentop::faultmatrix
