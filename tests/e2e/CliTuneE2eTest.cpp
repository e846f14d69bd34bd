// opentop-cli tune against an opentop-sim process over a pty: nothing moves without --yes or
// outside a closed-loop mode, a step test's report, a limit that stops the motor mid-test, and
// the autotune writing its gains only with --accept.
#include "CliProcess.h"
#include "SimProcess.h"

#include <QElapsedTimer>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QThread>
#include <csignal>

using namespace opentop::test;

namespace {

QStringList tune(const QStringList& rest)
{
    return QStringList{QStringLiteral("tune"), QStringLiteral("7")} + rest;
}

} // namespace

TEST(CliTuneE2e, StepTestAutotuneAndLimits)
{
    SimProcess sim;
    QString error;
    ASSERT_TRUE(sim.start({QStringLiteral("--devices"), QStringLiteral("dcpid@7")}, &error))
        << error.toStdString();
    const QStringList step = {QStringLiteral("step"), QStringLiteral("--from"),
                              QStringLiteral("100"), QStringLiteral("--to"), QStringLiteral("400")};

    CliResult r = runCliOn(sim.pty, tune(step));
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.err.contains(QStringLiteral("--yes"))) << r.err.toStdString();
    r = runCliOn(sim.pty, tune(step + QStringList{QStringLiteral("--yes")}));
    EXPECT_EQ(r.code, 3) << r.err.toStdString(); // PWM mode: refused, nothing moved
    EXPECT_TRUE(r.out.contains(QStringLiteral("closed-loop"))) << r.out.toStdString();
    EXPECT_EQ(sim.get(7, 0x0010, 3), 0);

    sim.command(QStringLiteral("set 7 0x0080 2"));
    r = runCliOn(sim.pty, tune(step + QStringList{QStringLiteral("--yes")}), 30000);
    ASSERT_EQ(r.code, 0) << (r.out + r.err).toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("settling time (2 %): "))) << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("motor stopped (confirmed)"))) << r.out.toStdString();
    EXPECT_EQ(sim.get(7, 0x0012, 3), 0);
    EXPECT_EQ(sim.get(7, 0x008E, 3), 0); // communication-loss time as it was

    // High gains overshoot beyond the limit: stopped at once.
    sim.command(QStringLiteral("set 7 0x0090 0x4120")); // P = 10.0
    sim.command(QStringLiteral("set 7 0x0091 0"));
    r = runCliOn(sim.pty,
                 tune(step + QStringList{QStringLiteral("--max-speed"), QStringLiteral("410"),
                                         QStringLiteral("--yes")}),
                 30000);
    EXPECT_EQ(r.code, 5) << (r.out + r.err).toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("beyond the test's limit 410")))
        << r.out.toStdString();
    EXPECT_EQ(sim.get(7, 0x0012, 3), 0);

    // Autotune without --accept proposes and leaves the gains alone; with it, writes them.
    const QStringList autotune = {QStringLiteral("autotune"), QStringLiteral("--speed"),
                                  QStringLiteral("400"), QStringLiteral("--yes"),
                                  QStringLiteral("--json")};
    r = runCliOn(sim.pty, tune(autotune), 30000);
    ASSERT_EQ(r.code, 0) << (r.out + r.err).toStdString();
    const QJsonObject json = QJsonDocument::fromJson(r.out.toUtf8()).object();
    const double proposedP =
        json.value(QStringLiteral("proposal")).toObject().value(QStringLiteral("p")).toDouble();
    EXPECT_GT(proposedP, 0.5) << r.out.toStdString();
    EXPECT_LT(proposedP, 10) << r.out.toStdString();
    EXPECT_EQ(sim.get(7, 0x0090, 3), 0x4120); // still P = 10
    EXPECT_EQ(sim.get(7, 0x0080, 3), 2);      // the closed-loop mode is back

    r = runCliOn(sim.pty, tune(autotune + QStringList{QStringLiteral("--accept")}), 30000);
    ASSERT_EQ(r.code, 0) << (r.out + r.err).toStdString();
    const QJsonObject accepted = QJsonDocument::fromJson(r.out.toUtf8()).object();
    EXPECT_TRUE(accepted.contains(QStringLiteral("measured"))) << r.out.toStdString();
    const int acceptedP = sim.get(7, 0x0090, 3);
    EXPECT_NE(acceptedP, 0x4120);
    // Accepted but not stored: a power cycle brings the stored gains back (P = 0.1).
    sim.command(QStringLiteral("power-cycle 7"));
    EXPECT_EQ(sim.get(7, 0x0090, 3), 0x3DCC);
    // With --store they survive it.
    sim.command(QStringLiteral("set 7 0x0080 2"));
    r = runCliOn(
        sim.pty,
        tune(autotune + QStringList{QStringLiteral("--accept"), QStringLiteral("--store")}), 30000);
    ASSERT_EQ(r.code, 0) << (r.out + r.err).toStdString();
    const int storedP = sim.get(7, 0x0090, 3);
    EXPECT_NE(storedP, 0x3DCC);
    sim.command(QStringLiteral("power-cycle 7"));
    EXPECT_EQ(sim.get(7, 0x0090, 3), storedP);
    EXPECT_EQ(sim.terminate(), 0);
}

TEST(CliTuneE2e, CtrlCStopsTheMotorBeforeTheCommandEnds)
{
    SimProcess sim;
    ASSERT_TRUE(sim.start({QStringLiteral("--devices"), QStringLiteral("dcpid@7")}));
    sim.command(QStringLiteral("set 7 0x0080 2"));
    QProcess p;
    p.start(cliProgram(),
            {QStringLiteral("--port"), sim.pty, QStringLiteral("tune"), QStringLiteral("7"),
             QStringLiteral("step"), QStringLiteral("--to"), QStringLiteral("400"),
             QStringLiteral("--record"), QStringLiteral("20000"), QStringLiteral("--yes")});
    ASSERT_TRUE(p.waitForStarted(5000));
    QString err;
    QElapsedTimer timer;
    timer.start();
    while (!err.contains(QStringLiteral("Step to")) && timer.elapsed() < 10000) {
        p.waitForReadyRead(200);
        err += QString::fromUtf8(p.readAllStandardError());
    }
    ASSERT_TRUE(err.contains(QStringLiteral("Step to"))) << err.toStdString();
    QThread::msleep(300);
    EXPECT_GT(sim.get(7, 0x0012, 3), 300); // running
    ::kill(pid_t(p.processId()), SIGINT);
    ASSERT_TRUE(p.waitForFinished(10000));
    EXPECT_EQ(p.exitCode(), 130);
    const QString out = QString::fromUtf8(p.readAllStandardOutput());
    EXPECT_TRUE(out.contains(QStringLiteral("motor stopped (confirmed)"))) << out.toStdString();
    EXPECT_EQ(sim.get(7, 0x0012, 3), 0);
    EXPECT_EQ(sim.get(7, 0x008E, 3), 0);
    EXPECT_EQ(sim.terminate(), 0);
}
