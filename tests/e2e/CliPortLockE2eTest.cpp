// Two programs, one port (issue 11, section 5): a second opentop-cli on a port another one holds
// is refused with the holder's name and PID and sends nothing; a SIGKILLed opentop-cli's lock
// does not block the next run. Real processes over the simulator's pty.
#include "tests/e2e/CliProcess.h"
#include "tests/e2e/SimProcess.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QThread>
#include <csignal>

using namespace opentop::test;

namespace {

bool startSim(SimProcess& sim)
{
    QString error;
    const bool ok = sim.start({QStringLiteral("--devices"), QStringLiteral("dbu200@1"),
                               QStringLiteral("--wire-timing"), QStringLiteral("--baud"),
                               QStringLiteral("19200")},
                              &error, false);
    EXPECT_TRUE(ok) << error.toStdString();
    return ok;
}

// opentop-cli --port PTY monitor 1, running until killed; returns once it has sampled.
bool startMonitor(QProcess& monitor, const QString& pty)
{
    monitor.start(cliProgram(),
                  {QStringLiteral("--port"), pty, QStringLiteral("--variant"),
                   QStringLiteral("1=dbu200"), QStringLiteral("monitor"), QStringLiteral("1"),
                   QStringLiteral("--interval"), QStringLiteral("200")});
    if (!monitor.waitForStarted(5000))
        return false;
    QByteArray out;
    for (int i = 0; i < 100 && out.count('\n') < 2; ++i) {
        monitor.waitForReadyRead(100);
        out += monitor.readAllStandardOutput();
    }
    return out.count('\n') >= 2;
}

QString lockFileOf(const QString& pty)
{
    QString name = QFileInfo(pty).canonicalFilePath().mid(5); // "pts/3"
    return QStringLiteral("/run/lock/LCK..") + name.replace(QLatin1Char('/'), QLatin1Char('_'));
}

} // namespace

TEST(CliPortLockE2e, ASecondOpenTopIsRefusedNamingTheHolderAndSendsNothing)
{
    SimProcess sim;
    ASSERT_TRUE(startSim(sim));
    QProcess monitor;
    ASSERT_TRUE(startMonitor(monitor, sim.pty)) << monitor.readAllStandardError().toStdString();
    const qint64 holder = monitor.processId();
    // The conventional lock file names the holder, where the system lets us write one.
    if (QFileInfo(QStringLiteral("/run/lock")).isWritable()) {
        QFile file(lockFileOf(sim.pty));
        ASSERT_TRUE(file.open(QIODevice::ReadOnly)) << file.fileName().toStdString();
        const QList<QByteArray> lines = file.readAll().split('\n');
        EXPECT_EQ(lines.value(0).toLongLong(), holder);
        EXPECT_EQ(lines.value(1), QByteArray("opentop-cli"));
    }

    const CliResult r =
        runCliOn(sim.pty, {QStringLiteral("scan"), QStringLiteral("--from"), QStringLiteral("5"),
                           QStringLiteral("--to"), QStringLiteral("6")});
    EXPECT_EQ(r.code, 1) << r.out.toStdString() << r.err.toStdString(); // ExitCommunication
    EXPECT_EQ(r.err.trimmed(), QStringLiteral("error: %1 is in use by opentop-cli (PID %2); close "
                                              "it first.")
                                   .arg(sim.pty)
                                   .arg(holder))
        << r.err.toStdString();
    QString trace; // the simulator's frame trace since the monitor had started
    for (int i = 0; i < 5; ++i) {
        sim.process().waitForReadyRead(100);
        trace += QString::fromLocal8Bit(sim.process().readAllStandardError());
    }
    EXPECT_TRUE(trace.contains(QStringLiteral("rx 01 ")))
        << "the holder keeps working: " << trace.toStdString();
    EXPECT_FALSE(trace.contains(QStringLiteral("rx 05 "))) << trace.toStdString();
    EXPECT_FALSE(trace.contains(QStringLiteral("rx 06 "))) << trace.toStdString();
    EXPECT_EQ(monitor.state(), QProcess::Running);

    // Once the holder has gone, the port is free (and its lock file gone with it).
    ::kill(pid_t(holder), SIGINT);
    ASSERT_TRUE(monitor.waitForFinished(5000));
    EXPECT_FALSE(QFile::exists(lockFileOf(sim.pty)));
    const CliResult again =
        runCliOn(sim.pty, {QStringLiteral("scan"), QStringLiteral("--from"), QStringLiteral("1"),
                           QStringLiteral("--to"), QStringLiteral("1")});
    EXPECT_EQ(again.code, 0) << again.err.toStdString();
}

TEST(CliPortLockE2e, AKilledOpenTopsLockDoesNotBlockTheNextRun)
{
    SimProcess sim;
    ASSERT_TRUE(startSim(sim));
    QProcess monitor;
    ASSERT_TRUE(startMonitor(monitor, sim.pty)) << monitor.readAllStandardError().toStdString();
    const qint64 killed = monitor.processId();
    ::kill(pid_t(killed), SIGKILL);
    ASSERT_TRUE(monitor.waitForFinished(5000));
    const QString file = lockFileOf(sim.pty);
    const bool lockFiles = QFileInfo(QStringLiteral("/run/lock")).isWritable();
    if (lockFiles) {
        // Left behind, naming a process that is gone: stale.
        QFile f(file);
        ASSERT_TRUE(f.open(QIODevice::ReadOnly));
        EXPECT_EQ(f.readAll().split('\n').value(0).toLongLong(), killed);
    }
    const CliResult r =
        runCliOn(sim.pty, {QStringLiteral("scan"), QStringLiteral("--from"), QStringLiteral("1"),
                           QStringLiteral("--to"), QStringLiteral("1")});
    EXPECT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("online"))) << r.out.toStdString();
    if (lockFiles) {
        EXPECT_FALSE(QFile::exists(file)) << "the stale file is removed, ours removed at exit";
    }
}
