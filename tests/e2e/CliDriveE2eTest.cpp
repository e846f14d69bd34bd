// The opentop-cli binary against an opentop-sim process over a pty: a test run, the live
// monitor (ended by --count and by Ctrl-C), alarms and stop-all.
#include "tests/e2e/CliProcess.h"
#include "tests/e2e/SimProcess.h"

#include <QElapsedTimer>
#include <QProcess>
#include <csignal>

using namespace opentop::test;

namespace {

CliResult cli(const QString& port, const QStringList& args, int timeoutMs = 20000)
{
    return runCliOn(port, args, timeoutMs);
}

QStringList lines(const QString& text)
{
    return text.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
}

} // namespace

TEST(CliDriveE2e, RunMonitorAndStopAllOverThePty)
{
    SimProcess sim;
    QString error;
    ASSERT_TRUE(
        sim.start({QStringLiteral("--devices"), QStringLiteral("dbu200@1,dcpid@7")}, &error))
        << error.toStdString();
    ASSERT_EQ(scanOn(sim.pty, 1, 8).code, 0);

    // In I/O priority the drive is left alone.
    CliResult r = cli(sim.pty, {QStringLiteral("run"), QStringLiteral("1"), QStringLiteral("start"),
                                QStringLiteral("--yes")});
    EXPECT_EQ(r.code, 3) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("core.control_priority=2"))) << r.err.toStdString();
    EXPECT_EQ(sim.get(1, 0x0109, 4), 0);

    // Communication priority through the simulator's console, then a test run.
    EXPECT_TRUE(sim.command(QStringLiteral("set 1 0x100D 2"))
                    .contains(QStringLiteral("0x100d"), Qt::CaseInsensitive));
    r = cli(sim.pty, {QStringLiteral("run"), QStringLiteral("1"), QStringLiteral("start"),
                      QStringLiteral("--yes")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("run.start = START (1)"))) << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("Running"))) << r.out.toStdString();

    r = cli(sim.pty, {QStringLiteral("monitor"), QStringLiteral("1"), QStringLiteral("7"),
                      QStringLiteral("--count"), QStringLiteral("3"), QStringLiteral("--interval"),
                      QStringLiteral("100")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    const QStringList monitored = lines(r.out);
    ASSERT_EQ(monitored.size(), 2 + 6) << r.out.toStdString(); // a header per family
    int running = 0;
    for (const QString& line : monitored)
        running +=
            line.contains(QStringLiteral("500 r/min")) && line.contains(QStringLiteral("Running"));
    EXPECT_GE(running, 1) << r.out.toStdString();

    r = cli(sim.pty, {QStringLiteral("stop-all"), QStringLiteral("--yes"), QStringLiteral("--ids"),
                      QStringLiteral("1,7")});
    EXPECT_EQ(r.code, 0) << (r.out + r.err).toStdString();
    EXPECT_EQ(r.out.count(QStringLiteral("stopped")), 2) << r.out.toStdString();
    EXPECT_EQ(sim.get(1, 0x0109, 4), 0);

    // Without --ids on a real line only the broadcast can be sent.
    r = cli(sim.pty, {QStringLiteral("stop-all"), QStringLiteral("--yes")});
    EXPECT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("Only the broadcast was sent")))
        << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("--ids"))) << r.out.toStdString();
    EXPECT_EQ(sim.terminate(), 0);
}

TEST(CliDriveE2e, AlarmsAndAStopThatIsIgnored)
{
    SimProcess sim;
    ASSERT_TRUE(sim.start({QStringLiteral("--devices"), QStringLiteral("dbu200@1,dbu400@2")}));
    ASSERT_EQ(scanOn(sim.pty, 1, 4).code, 0);
    sim.command(QStringLiteral("alarm 1 7"));
    CliResult r = cli(sim.pty, {QStringLiteral("alarms"), QStringLiteral("1")});
    EXPECT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("AL007  Overload"))) << r.out.toStdString();
    r = cli(sim.pty, {QStringLiteral("alarms"), QStringLiteral("1"), QStringLiteral("--reset"),
                      QStringLiteral("--yes")});
    EXPECT_EQ(r.code, 0) << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("AL007 Overload is cleared.")))
        << r.out.toStdString();

    for (int id : {1, 2}) {
        sim.command(QStringLiteral("set %1 0x100D 2").arg(id));
        EXPECT_EQ(cli(sim.pty, {QStringLiteral("run"), QString::number(id), QStringLiteral("start"),
                                QStringLiteral("--yes")})
                      .code,
                  0);
    }
    sim.command(QStringLiteral("ignore-stop 2 on"));
    r = cli(sim.pty, {QStringLiteral("stop-all"), QStringLiteral("--yes"), QStringLiteral("--ids"),
                      QStringLiteral("1-2")});
    EXPECT_EQ(r.code, 4) << (r.out + r.err).toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("STILL RUNNING"))) << r.out.toStdString();
    EXPECT_EQ(sim.terminate(), 0);
}

TEST(CliDriveE2e, MonitorEndsOnCtrlC)
{
    SimProcess sim;
    ASSERT_TRUE(sim.start({QStringLiteral("--devices"), QStringLiteral("dbu200@1")}));
    QProcess p;
    p.start(cliProgram(),
            {QStringLiteral("--port"), sim.pty, QStringLiteral("monitor"), QStringLiteral("1"),
             QStringLiteral("--interval"), QStringLiteral("50")});
    ASSERT_TRUE(p.waitForStarted(5000));
    // Wait for a header and two samples, then interrupt.
    QString out;
    QElapsedTimer timer;
    timer.start();
    while (lines(out).size() < 3 && timer.elapsed() < 10000) {
        p.waitForReadyRead(200);
        out += QString::fromUtf8(p.readAllStandardOutput());
    }
    ASSERT_GE(lines(out).size(), 3) << out.toStdString();
    ::kill(pid_t(p.processId()), SIGINT);
    ASSERT_TRUE(p.waitForFinished(5000));
    EXPECT_EQ(p.exitCode(), 130);
    EXPECT_EQ(sim.terminate(), 0);
}
