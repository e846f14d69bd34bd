// opentop-cli against an opentop-sim process over a pty: a dropped session (SIGHUP) during a
// restore is reported like Ctrl-C, and wrong connection options are usage errors before the
// port is touched. Real processes, exit codes and messages.
#include "tests/e2e/CliProcess.h"
#include "tests/e2e/SimProcess.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QTemporaryDir>
#include <csignal>

using namespace opentop::test;

namespace {

class CliFaultsE2e : public ::testing::Test
{
protected:
    void SetUp() override
    {
        QString error;
        ASSERT_TRUE(sim.start({QStringLiteral("--devices"), QStringLiteral("dbu200@1"),
                               QStringLiteral("--wire-timing"), QStringLiteral("--baud"),
                               QStringLiteral("19200")},
                              &error))
            << error.toStdString();
        ASSERT_TRUE(dir.isValid());
        file = dir.filePath(QStringLiteral("drive1.json"));
    }

    QStringList arguments(const QStringList& command) const
    {
        return QStringList{QStringLiteral("--port"), sim.pty, QStringLiteral("--variant"),
                           QStringLiteral("1=dbu200"), QStringLiteral("--bus-drives=1")} +
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

TEST_F(CliFaultsE2e, AHangupStopsARestoreBetweenTransactionsWithAReport)
{
    ASSERT_EQ(run({QStringLiteral("backup"), QStringLiteral("1"), QStringLiteral("-o"), file}).code,
              0);
    for (int spno = 0; spno < 7; ++spno) {
        for (int base : {0x1303, 0x4503})
            sim.command(
                QStringLiteral("set 1 0x%1 100").arg(base + 2 * spno, 4, 16, QLatin1Char('0')));
    }
    QProcess cli;
    cli.start(cliProgram(), arguments({QStringLiteral("restore"), file, QStringLiteral("--yes"),
                                       QStringLiteral("--trace")}));
    ASSERT_TRUE(cli.waitForStarted(5000));
    QString trace;
    QElapsedTimer timer;
    timer.start();
    while (!trace.contains(QStringLiteral(" 01 06 ")) && timer.elapsed() < 10000) {
        cli.waitForReadyRead(100);
        trace += QString::fromUtf8(cli.readAllStandardError());
    }
    ASSERT_TRUE(trace.contains(QStringLiteral(" 01 06 "))) << trace.toStdString();
    ::kill(pid_t(cli.processId()), SIGHUP); // the ssh session dropped
    CliResult r = finishCli(cli);
    EXPECT_EQ(r.code, 130) << (r.out + r.err).toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("not attempted"))) << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("run the restore again to complete it")))
        << r.out.toStdString();
    EXPECT_EQ(sim.get(1, 0x450F), 100); // the last write: not reached

    r = run({QStringLiteral("restore"), file, QStringLiteral("--yes")});
    EXPECT_EQ(r.code, 0) << (r.out + r.err).toStdString();
    EXPECT_EQ(sim.get(1, 0x450F), 5);
}

TEST_F(CliFaultsE2e, WrongConnectionOptionsExit2AndSendNothing)
{
    const QStringList wrong[] = {
        {QStringLiteral("--baud"), QStringLiteral("123")},
        {QStringLiteral("--timeout"), QStringLiteral("0")},
        {QStringLiteral("--retries"), QStringLiteral("11")},
        {QStringLiteral("--parity"), QStringLiteral("X")},
        {QStringLiteral("--stop-bits"), QStringLiteral("3")},
        {QStringLiteral("--family"), QStringLiteral("xyz")},
    };
    for (const QStringList& option : wrong) {
        const CliResult r =
            run(option + QStringList{QStringLiteral("--trace"), QStringLiteral("get"),
                                     QStringLiteral("1"), QStringLiteral("spno2.speed")});
        EXPECT_EQ(r.code, 2) << (option.join(QLatin1Char(' ')) + r.err).toStdString();
        EXPECT_TRUE(r.err.contains(QStringLiteral("use "))) << r.err.toStdString();
        EXPECT_FALSE(r.err.contains(QStringLiteral("not checked"))) << r.err.toStdString();
        EXPECT_FALSE(r.err.contains(QStringLiteral(" 01 03 "))) << r.err.toStdString();
    }
}
