// opentop-cli's RS-485 and low-latency options against opentop-sim over a pty: the programs say
// what the driver accepted (a pty takes neither RS-485 mode nor RTS, and is no UART), and the
// scan still finds the drive.
#include "tests/e2e/CliProcess.h"
#include "tests/e2e/SimProcess.h"

using namespace opentop::test;

namespace {

bool startSim(SimProcess& sim)
{
    QString error;
    const bool ok = sim.start({QStringLiteral("--devices"), QStringLiteral("dbu200@1")}, &error);
    EXPECT_TRUE(ok) << error.toStdString();
    return ok;
}

CliResult scan(const SimProcess& sim, const QStringList& lineOptions)
{
    return runCliOn(sim.pty,
                    lineOptions + QStringList{QStringLiteral("scan"), QStringLiteral("--from"),
                                              QStringLiteral("1"), QStringLiteral("--to"),
                                              QStringLiteral("2")});
}

} // namespace

TEST(CliSerialLineE2e, ScanSaysWhatTheDriverAcceptedAndStillFindsTheDrive)
{
    SimProcess sim;
    ASSERT_TRUE(startSim(sim));
    CliResult r = scan(sim, {QStringLiteral("--rs485"), QStringLiteral("kernel")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("1 drive found"))) << r.out.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral(" rs485=kernel, "))) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("Serial line: RS-485: kernel mode refused by the "
                                              "driver (Inappropriate ioctl for device); low "
                                              "latency: not a UART, no adapter latency")))
        << r.err.toStdString();
    // Nothing held back on a pty: no latency warning.
    EXPECT_FALSE(r.err.contains(QStringLiteral("warning:"))) << r.err.toStdString();

    r = scan(sim, {QStringLiteral("--rs485"), QStringLiteral("auto"), QStringLiteral("--rts-delay"),
                   QStringLiteral("500")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("Serial line: RS-485: not available (kernel mode "
                                              "refused: Inappropriate ioctl for device; RTS not "
                                              "switchable: Inappropriate ioctl for device)")))
        << r.err.toStdString();

    r = scan(sim, {});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("Serial line: RS-485: switched by the adapter; low "
                                              "latency: not a UART, no adapter latency")))
        << r.err.toStdString();

    // --trace says it for any command.
    r = runCliOn(sim.pty,
                 {QStringLiteral("--rs485"), QStringLiteral("rts"), QStringLiteral("--trace"),
                  QStringLiteral("--variant"), QStringLiteral("1=dbu200"), QStringLiteral("get"),
                  QStringLiteral("1"), QStringLiteral("spno1.speed")});
    EXPECT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("serial line: RS-485: RTS not switchable on this "
                                              "port (Inappropriate ioctl for device)")))
        << r.err.toStdString();
    EXPECT_EQ(sim.terminate(), 0);
}

TEST(CliSerialLineE2e, WrongValuesAndASimulatedBusAreUsageErrors)
{
    QProcess cli;
    cli.start(cliProgram(),
              {QStringLiteral("--port"), QStringLiteral("/dev/opentop-no-such-port"),
               QStringLiteral("--low-latency"), QStringLiteral("maybe"), QStringLiteral("scan")});
    ASSERT_TRUE(cli.waitForStarted(5000));
    CliResult r = finishCli(cli);
    EXPECT_EQ(r.code, 2) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("--low-latency maybe: use on or off")))
        << r.err.toStdString();

    cli.start(cliProgram(),
              {QStringLiteral("--sim"), QStringLiteral("dbu200@1"), QStringLiteral("--rs485"),
               QStringLiteral("auto"), QStringLiteral("scan")});
    ASSERT_TRUE(cli.waitForStarted(5000));
    r = finishCli(cli);
    EXPECT_EQ(r.code, 2) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("--rs485 applies to a serial port (--port), not to "
                                              "a simulated bus")))
        << r.err.toStdString();
}
