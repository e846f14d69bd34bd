// get and set through the opentop-cli executable over a pty against an opentop-sim process:
// the values reach the drive (checked through the simulator's own console), a wrong value sends
// nothing, and injected faults are survived by retries or reported.
#include "tests/e2e/CliProcess.h"
#include "tests/e2e/SimProcess.h"

#include <QProcess>

using namespace opentop::test;

namespace {

CliResult cli(const SimProcess& sim, const QStringList& args)
{
    return runCliOn(sim.pty, args);
}

} // namespace

TEST(CliParameterE2e, SetReachesTheDriveAndAWrongValueSendsNothing)
{
    SimProcess sim;
    QString error;
    ASSERT_TRUE(
        sim.start({QStringLiteral("--devices"), QStringLiteral("dbu400@150,dcpid@7")}, &error))
        << qPrintable(error);
    ASSERT_EQ(scanOn(sim.pty, 150, 150).code, 0);
    CliResult r = cli(sim, {QStringLiteral("--variant"), QStringLiteral("dbu400"),
                            QStringLiteral("set"), QStringLiteral("150"),
                            QStringLiteral("spno2.speed=1800"), QStringLiteral("spno2.accel=2.5")});
    ASSERT_EQ(r.code, 0) << qPrintable(r.err);
    EXPECT_EQ(sim.get(150, 0xCA03), 1800);
    EXPECT_EQ(sim.get(150, 0x1303), 25);

    r = cli(sim, {QStringLiteral("--variant"), QStringLiteral("dbu400"), QStringLiteral("set"),
                  QStringLiteral("150"), QStringLiteral("spno2.speed=280"),
                  QStringLiteral("spno2.accel=3")});
    EXPECT_EQ(r.code, 3);
    EXPECT_TRUE(r.err.contains(QStringLiteral("0 or 300–3000 r/min"))) << qPrintable(r.err);
    EXPECT_EQ(sim.get(150, 0xCA03), 1800);
    EXPECT_EQ(sim.get(150, 0x1303), 25); // the valid value in the same command was not sent either

    // The DC controller's 32-bit baud rate (opentop-sim sets it to its line speed) and float
    // PID coefficient read back in engineering units.
    r = cli(sim, {QStringLiteral("get"), QStringLiteral("7"), QStringLiteral("config.baud"),
                  QStringLiteral("pid.p"), QStringLiteral("--json")});
    ASSERT_EQ(r.code, 0) << qPrintable(r.err);
    EXPECT_TRUE(r.out.contains(QStringLiteral("\"19200 bit/s\""))) << qPrintable(r.out);
    EXPECT_TRUE(r.out.contains(QStringLiteral("\"0.1000\""))) << qPrintable(r.out);
    sim.terminate();
}

TEST(CliParameterE2e, RetriesCarryReadsThroughDroppedRepliesAndFailuresAreReported)
{
    SimProcess sim;
    QString error;
    ASSERT_TRUE(sim.start({QStringLiteral("--devices"), QStringLiteral("dbu200@1"),
                           QStringLiteral("--faults"), QStringLiteral("drop=0.3"),
                           QStringLiteral("--seed"), QStringLiteral("4")},
                          &error))
        << qPrintable(error);
    const QStringList read = {QStringLiteral("--timeout"), QStringLiteral("60"),
                              QStringLiteral("--retries"), QStringLiteral("5"),
                              QStringLiteral("get"),       QStringLiteral("1"),
                              QStringLiteral("--group"),   QStringLiteral("running")};
    CliResult r = cli(sim, read);
    EXPECT_EQ(r.code, 0) << qPrintable(r.err);
    EXPECT_TRUE(r.out.contains(QStringLiteral("spno8.speed"))) << qPrintable(r.out);
    // Without retries the same faults make reads fail, and the command says so with exit 1.
    int failures = 0;
    for (int i = 0; i < 3; ++i) {
        r = cli(sim, {QStringLiteral("--timeout"), QStringLiteral("60"),
                      QStringLiteral("--retries"), QStringLiteral("0"), QStringLiteral("get"),
                      QStringLiteral("1"), QStringLiteral("--group"), QStringLiteral("running")});
        if (r.code == 1) {
            ++failures;
            EXPECT_TRUE(r.err.contains(QStringLiteral("could not be read")) ||
                        r.err.contains(QStringLiteral("no answer")))
                << qPrintable(r.err);
        } else {
            EXPECT_EQ(r.code, 0) << qPrintable(r.err);
        }
    }
    EXPECT_GT(failures, 0);
    sim.terminate();
}
