// opentop-cli tune against an opentop-sim process over a pty: nothing moves without --yes or
// outside a closed-loop mode, a step test's report, a limit that stops the motor mid-test, the
// autotune writing its gains only with --accept, a relay on a 19200 bit/s line refused with what
// to change, and a failed check after --accept writing the gains back unless --override-check.
#include "tests/e2e/CliProcess.h"
#include "tests/e2e/SimProcess.h"

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

// The case over a real pty: 19200 bit/s, wire timing, a half-duplex line; 300 1/s, 10 %,
// medium. The relay's period holds too few readings: refused with why and what to change, exit
// 5, the gains untouched, the motor stopped and the closed loop back.
TEST(CliTuneE2e, ARelayTheBusCannotResolveIsRefusedWithWhatToChange)
{
    SimProcess sim;
    QString error;
    ASSERT_TRUE(sim.start({QStringLiteral("--devices"), QStringLiteral("dcpid@7"),
                           QStringLiteral("--baud"), QStringLiteral("19200"),
                           QStringLiteral("--wire-timing"), QStringLiteral("--half-duplex")},
                          &error))
        << error.toStdString();
    sim.command(QStringLiteral("set 7 0x0080 2"));
    const QStringList args = {QStringLiteral("--baud"),   QStringLiteral("19200"),
                              QStringLiteral("tune"),     QStringLiteral("7"),
                              QStringLiteral("autotune"), QStringLiteral("--speed"),
                              QStringLiteral("300"),      QStringLiteral("--accept"),
                              QStringLiteral("--store"),  QStringLiteral("--yes")};
    CliResult r = runCliOn(sim.pty, args, 60000);
    EXPECT_EQ(r.code, 5) << (r.out + r.err).toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("readings"))) << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("What to change: Raise the line rate")))
        << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("motor stopped (confirmed)"))) << r.out.toStdString();
    EXPECT_FALSE(r.out.contains(QStringLiteral("Proposed"))) << r.out.toStdString();
    EXPECT_EQ(sim.get(7, 0x0090, 3), 0x3DCC); // P 0.1, as it was
    EXPECT_EQ(sim.get(7, 0x0080, 3), 2);
    EXPECT_EQ(sim.get(7, 0x0012, 3), 0);
    r = runCliOn(sim.pty, args + QStringList{QStringLiteral("--json")}, 60000);
    EXPECT_EQ(r.code, 5);
    const QJsonObject json = QJsonDocument::fromJson(r.out.toUtf8()).object();
    EXPECT_FALSE(json.value(QStringLiteral("ok")).toBool());
    EXPECT_TRUE(
        json.value(QStringLiteral("advice")).toString().contains(QStringLiteral("line rate")))
        << r.out.toStdString();
    EXPECT_EQ(sim.terminate(), 0);
}

namespace {

// `tune 7 autotune ... --accept --store` on `sim`; once the check's step begins, the motor is
// coupled to another load (a longer speed gate, a faster motor) that the accepted gains do not
// suit.
CliResult acceptOnAChangedPlant(SimProcess& sim, const QStringList& extra)
{
    QProcess p;
    p.start(cliProgram(),
            QStringList{QStringLiteral("--port"), sim.pty, QStringLiteral("--baud"),
                        QStringLiteral("115200"), QStringLiteral("tune"), QStringLiteral("7"),
                        QStringLiteral("autotune"), QStringLiteral("--speed"),
                        QStringLiteral("300"), QStringLiteral("--max-speed"), QStringLiteral("600"),
                        QStringLiteral("--accept"), QStringLiteral("--store"),
                        QStringLiteral("--yes")} +
                extra);
    if (!p.waitForStarted(5000))
        return {};
    QString err;
    QElapsedTimer timer;
    timer.start();
    while (!err.contains(QStringLiteral("Running to")) && timer.elapsed() < 30000 &&
           p.state() == QProcess::Running) {
        p.waitForReadyRead(100);
        err += QString::fromUtf8(p.readAllStandardError());
    }
    EXPECT_TRUE(err.contains(QStringLiteral("Running to"))) << err.toStdString();
    sim.command(QStringLiteral("motor 7 gate=100 no_load=2000"));
    CliResult r = finishCli(p, 60000);
    r.err = err + r.err;
    return r;
}

} // namespace

// The check after --accept fails (the plant changed): the gains the drive had are written back
// and nothing is stored (exit 5), unless --override-check, which stores them all the same.
TEST(CliTuneE2e, AFailedCheckWritesTheGainsBackUnlessOverridden)
{
    SimProcess sim;
    QString error;
    ASSERT_TRUE(sim.start({QStringLiteral("--devices"), QStringLiteral("dcpid@7"),
                           QStringLiteral("--baud"), QStringLiteral("115200"),
                           QStringLiteral("--wire-timing"), QStringLiteral("--half-duplex")},
                          &error))
        << error.toStdString();
    sim.command(QStringLiteral("set 7 0x0080 2"));
    CliResult r = acceptOnAChangedPlant(sim, {});
    EXPECT_EQ(r.code, 5) << (r.out + r.err).toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("Check after Accept: FAILED")))
        << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("overshot"))) << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("The gains before were written back (P 0.1000")))
        << r.out.toStdString();
    EXPECT_FALSE(r.out.contains(QStringLiteral("Gains stored"))) << r.out.toStdString();
    EXPECT_EQ(sim.get(7, 0x0090, 3), 0x3DCC);
    sim.command(QStringLiteral("power-cycle 7"));
    EXPECT_EQ(sim.get(7, 0x0090, 3), 0x3DCC); // nothing stored

    // --override-check: stored all the same, and said so.
    sim.command(QStringLiteral("motor 7 gate=25 no_load=1000"));
    sim.command(QStringLiteral("set 7 0x0080 2"));
    r = acceptOnAChangedPlant(sim, {QStringLiteral("--override-check")});
    EXPECT_EQ(r.code, 0) << (r.out + r.err).toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("Check after Accept: FAILED")))
        << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("Storing although the check failed")))
        << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("Gains stored in the drive.")))
        << r.out.toStdString();
    const int storedP = sim.get(7, 0x0090, 3);
    EXPECT_NE(storedP, 0x3DCC);
    sim.command(QStringLiteral("power-cycle 7"));
    EXPECT_EQ(sim.get(7, 0x0090, 3), storedP);
    EXPECT_EQ(sim.terminate(), 0);
}
