// opentop-cli backing up and restoring drives of an opentop-sim process over a pty with wire
// timing: real processes, the real RTU backend, files on disk, exit codes and Ctrl-C.
#include "tests/e2e/CliProcess.h"
#include "tests/e2e/SimProcess.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QTemporaryDir>
#include <csignal>

using namespace opentop::test;

namespace {

class CliBackupE2e : public ::testing::Test
{
protected:
    void SetUp() override
    {
        QString error;
        ASSERT_TRUE(sim.start({QStringLiteral("--devices"), QStringLiteral("dbu200@1,dcpid@7"),
                               QStringLiteral("--wire-timing"), QStringLiteral("--baud"),
                               QStringLiteral("19200")},
                              &error))
            << error.toStdString();
        ASSERT_TRUE(dir.isValid());
        file = dir.filePath(QStringLiteral("line3.json"));
    }

    QStringList arguments(const QStringList& command) const
    {
        return QStringList{QStringLiteral("--port"), sim.pty, QStringLiteral("--variant"),
                           QStringLiteral("1=dbu200"), QStringLiteral("--bus-drives=1,7")} +
               command;
    }

    CliResult run(const QStringList& command)
    {
        QProcess cli;
        cli.start(cliProgram(), arguments(command));
        EXPECT_TRUE(cli.waitForStarted(5000));
        return finishCli(cli);
    }

    SimProcess sim;
    QTemporaryDir dir;
    QString file;
};

} // namespace

TEST_F(CliBackupE2e, BackupThenRestoreOverThePty)
{
    CliResult r = run({QStringLiteral("backup"), QStringLiteral("1"), QStringLiteral("7"),
                       QStringLiteral("-o"), file});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_TRUE(
        r.out.contains(QStringLiteral("drive 1 (DBU200-D): 69 settings read in 12 requests")))
        << r.out.toStdString();
    EXPECT_TRUE(QFileInfo::exists(file));

    EXPECT_TRUE(sim.command(QStringLiteral("set 1 0xCA03 1500")).contains(QStringLiteral("1500")));
    EXPECT_TRUE(sim.command(QStringLiteral("set 7 0x0086 750")).contains(QStringLiteral("750")));
    r = run({QStringLiteral("restore"), file, QStringLiteral("--yes")});
    ASSERT_EQ(r.code, 0) << (r.out + r.err).toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("written and verified"))) << r.out.toStdString();
    EXPECT_EQ(sim.get(1, 0xCA03), 1000);
    EXPECT_EQ(sim.get(7, 0x0086), 500);
    sim.command(QStringLiteral("power-cycle 7"));
    EXPECT_EQ(sim.get(7, 0x0086), 500); // stored by the restore

    r = run({QStringLiteral("compare"), file + QStringLiteral(":7"), QStringLiteral("7")});
    EXPECT_EQ(r.code, 0);
    EXPECT_TRUE(r.out.contains(QStringLiteral("no differences"))) << r.out.toStdString();
}

TEST_F(CliBackupE2e, CtrlCStopsARestoreBetweenTransactionsAndASecondRunCompletes)
{
    ASSERT_EQ(run({QStringLiteral("backup"), QStringLiteral("1"), QStringLiteral("-o"), file}).code,
              0);
    // Fourteen differences: the acceleration and deceleration times of SPno2..SPno8.
    for (int spno = 0; spno < 7; ++spno) {
        for (int base : {0x1303, 0x4503})
            sim.command(
                QStringLiteral("set 1 0x%1 100").arg(base + 2 * spno, 4, 16, QLatin1Char('0')));
    }
    QProcess cli;
    cli.start(cliProgram(), arguments({QStringLiteral("restore"), file, QStringLiteral("--yes"),
                                       QStringLiteral("--trace")}));
    ASSERT_TRUE(cli.waitForStarted(5000));
    // Ctrl-C as soon as the first write frame is on the wire.
    QString trace;
    QElapsedTimer timer;
    timer.start();
    while (!trace.contains(QStringLiteral(" 01 06 ")) && timer.elapsed() < 10000) {
        cli.waitForReadyRead(100);
        trace += QString::fromUtf8(cli.readAllStandardError());
    }
    ASSERT_TRUE(trace.contains(QStringLiteral(" 01 06 "))) << trace.toStdString();
    ::kill(pid_t(cli.processId()), SIGINT);
    CliResult r = finishCli(cli);
    EXPECT_EQ(r.code, 130) << (r.out + r.err).toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("not attempted"))) << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("run the restore again to complete it")))
        << r.out.toStdString();
    EXPECT_EQ(sim.get(1, 0x450F), 100); // SPno8 deceleration, the last write: not reached

    r = run({QStringLiteral("restore"), file, QStringLiteral("--yes")});
    EXPECT_EQ(r.code, 0) << (r.out + r.err).toStdString();
    EXPECT_EQ(sim.get(1, 0x450F), 5);
    r = run({QStringLiteral("compare"), file, QStringLiteral("1")});
    EXPECT_TRUE(r.out.contains(QStringLiteral("no differences"))) << r.out.toStdString();
}
