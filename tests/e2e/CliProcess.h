#pragma once

// Runs the opentop-cli executable as a separate process for end-to-end tests.
#include <QProcess>
#include <QString>
#include <QStringList>

namespace opentop::test {

struct CliResult
{
    int code = -1; // -1: crashed or killed
    QString out;
    QString err;
};

inline QString cliProgram()
{
    return QStringLiteral(OPENTOP_BIN_DIR "/opentop-cli");
}

// Collects a started process's exit code and output; kills it after `timeoutMs`.
inline CliResult finishCli(QProcess& process, int timeoutMs = 30000)
{
    CliResult r;
    if (!process.waitForFinished(timeoutMs)) {
        process.kill();
        process.waitForFinished(2000);
        r.err = QStringLiteral("<timed out>");
        return r;
    }
    r.code = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
    r.out = QString::fromUtf8(process.readAllStandardOutput());
    r.err = QString::fromUtf8(process.readAllStandardError());
    return r;
}

// opentop-cli --port PORT ARGS...
inline CliResult runCliOn(const QString& port, const QStringList& args, int timeoutMs = 30000)
{
    QProcess process;
    process.start(cliProgram(), QStringList{QStringLiteral("--port"), port} + args);
    if (!process.waitForStarted(5000))
        return CliResult{-1, QString(), QStringLiteral("<cannot start opentop-cli>")};
    return finishCli(process, timeoutMs);
}

// opentop-cli --port PORT scan --from FROM --to TO: what a technician does first on a bus (the
// drives found are remembered, so writes and commands know the communication groups).
inline CliResult scanOn(const QString& port, int from, int to)
{
    return runCliOn(port, {QStringLiteral("scan"), QStringLiteral("--from"), QString::number(from),
                           QStringLiteral("--to"), QString::number(to)});
}

} // namespace opentop::test
