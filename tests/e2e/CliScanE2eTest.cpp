// The opentop-cli executable scanning an opentop-sim process over a pty with wire timing: the
// real RTU backend, real processes, real exit codes and signals. Small ranges keep it fast.
#include "tests/e2e/CliProcess.h"
#include "tests/e2e/SimProcess.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QThread>
#include <csignal>

using namespace opentop::test;

namespace {

CliResult runScan(const SimProcess& sim, const QStringList& args)
{
    QProcess cli;
    cli.start(cliProgram(),
              QStringList{QStringLiteral("--port"), sim.pty, QStringLiteral("scan")} + args);
    EXPECT_TRUE(cli.waitForStarted(5000));
    return finishCli(cli);
}

bool startSim(SimProcess& sim, const QString& devices, const QStringList& extra = {})
{
    QString error;
    const bool ok =
        sim.start(QStringList{QStringLiteral("--devices"), devices, QStringLiteral("--wire-timing"),
                              QStringLiteral("--baud"), QStringLiteral("19200")} +
                      extra,
                  &error);
    EXPECT_TRUE(ok) << error.toStdString();
    return ok;
}

QString row(const QString& out, int slave)
{
    for (const QString& line : out.split(QLatin1Char('\n'))) {
        if (line.trimmed().startsWith(QString::number(slave) + QLatin1Char(' ')))
            return line.simplified();
    }
    return QString();
}

} // namespace

TEST(CliScanE2e, FindsTheDrivesOfASimulatedLine)
{
    SimProcess sim;
    ASSERT_TRUE(startSim(sim, QStringLiteral("dbu200@1,dcpid@7,dbu400@18,dbu200@150")));
    const CliResult r = runScan(sim, {QStringLiteral("--from"), QStringLiteral("1"),
                                      QStringLiteral("--to"), QStringLiteral("20")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    // A separate process gets no simulated bus list: the DBU variants stay unknown.
    EXPECT_EQ(row(r.out, 1),
              QStringLiteral("1 01h SW1=0 SW2=1 dbu DBU — variant unknown V1.5 online"))
        << r.out.toStdString();
    // The DC controller's own switches: DIP 1–7 in binary, not the DBU's SW1/SW2.
    EXPECT_EQ(row(r.out, 7), QStringLiteral("7 07h DIP ON: 1,2,3 dcpid DCPID-20A V1.0 online"));
    EXPECT_EQ(row(r.out, 18),
              QStringLiteral("18 12h SW1=1 SW2=2 dbu DBU — variant unknown V1.5 online"));
    EXPECT_TRUE(row(r.out, 150).isEmpty());
    EXPECT_TRUE(r.out.contains(QStringLiteral("3 drives found in "))) << r.out.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("Scanning machine numbers 1–20 on ")));
    EXPECT_TRUE(r.err.contains(QStringLiteral("scan: 100 % (20 of 20 machine numbers), 3 found")))
        << r.err.toStdString();
    EXPECT_EQ(sim.terminate(), 0);
}

TEST(CliScanE2e, VariantOptionAndNoDriveInRange)
{
    SimProcess sim;
    ASSERT_TRUE(startSim(sim, QStringLiteral("dbu400@30")));
    CliResult r = runScan(sim, {QStringLiteral("--from"), QStringLiteral("30"),
                                QStringLiteral("--to"), QStringLiteral("31"),
                                QStringLiteral("--variant"), QStringLiteral("30=dbu400")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_EQ(row(r.out, 30), QStringLiteral("30 1Eh SW1=1 SW2=E dbu DBU400-D4 V1.5 online"));

    r = runScan(sim, {QStringLiteral("--from"), QStringLiteral("1"), QStringLiteral("--to"),
                      QStringLiteral("4")});
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.err.contains(QStringLiteral("A/B polarity"))) << r.err.toStdString();
}

TEST(CliScanE2e, GarbledRepliesAreReportedAsAPossibleDuplicate)
{
    SimProcess sim;
    // Every reply of the drive at 3 arrives with a broken CRC, as when two drives answer at once.
    ASSERT_TRUE(startSim(sim, QStringLiteral("dbu200@3"),
                         {QStringLiteral("--faults"), QStringLiteral("crc=1")}));
    const CliResult r = runScan(sim, {QStringLiteral("--from"), QStringLiteral("1"),
                                      QStringLiteral("--to"), QStringLiteral("5")});
    EXPECT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_TRUE(row(r.out, 3).contains(QStringLiteral("garbled replies"))) << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("1 possible duplicate machine number: 3")))
        << r.out.toStdString();
    // Which family answers is not known: the switches of each family that can have number 3.
    EXPECT_TRUE(r.err.contains(
        QStringLiteral("warning: machine number 3 (03h  DBU SW1=0 SW2=3 / DCPID DIP ON: 1,2)")))
        << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("address switches")));
}

TEST(CliScanE2e, CtrlCStopsTheScanAndReportsWhatWasScanned)
{
    SimProcess sim;
    ASSERT_TRUE(startSim(sim, QStringLiteral("dbu200@2")));
    QProcess cli;
    cli.start(cliProgram(), {QStringLiteral("--port"), sim.pty, QStringLiteral("scan"),
                             QStringLiteral("--wait"), QStringLiteral("100")});
    ASSERT_TRUE(cli.waitForStarted(5000));
    // Wait until the scan is under way (progress after 10 % would take 2.5 s: read the banner).
    QElapsedTimer timer;
    timer.start();
    while (!cli.readAllStandardError().contains("Scanning") && timer.elapsed() < 5000)
        cli.waitForReadyRead(100);
    QThread::msleep(600);
    ::kill(pid_t(cli.processId()), SIGINT);
    timer.restart();
    const CliResult r = finishCli(cli);
    EXPECT_LT(timer.elapsed(), 2000);
    EXPECT_EQ(r.code, 130) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("Interrupted: machine numbers 1–")))
        << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("were not asked")));
    EXPECT_TRUE(row(r.out, 2).contains(QStringLiteral("online"))) << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("1 drive found in ")));
}

TEST(CliScanE2e, AnEmptyScanNamesTheOptionsThatFindADcControllerInPotentiometerMode)
{
    // A DC controller in potentiometer/analog control: 9600 8E1, address 1.
    SimProcess sim;
    QString error;
    ASSERT_TRUE(
        sim.start({QStringLiteral("--devices"), QStringLiteral("dcpid@1"), QStringLiteral("--baud"),
                   QStringLiteral("9600"), QStringLiteral("--parity"), QStringLiteral("E")},
                  &error))
        << error.toStdString();
    const CliResult empty =
        runScan(sim, {QStringLiteral("--from"), QStringLiteral("2"), QStringLiteral("--to"),
                      QStringLiteral("3"), QStringLiteral("--wait"), QStringLiteral("50")});
    EXPECT_EQ(empty.code, 1) << empty.err.toStdString();
    const QString marker = QStringLiteral("Retry with the same connection and: ");
    QString hint;
    for (const QString& line : empty.err.split(QLatin1Char('\n'))) {
        if (line.startsWith(QLatin1String("hint: ")) && line.contains(marker))
            hint = line.mid(line.indexOf(marker) + marker.size()).trimmed();
    }
    ASSERT_FALSE(hint.isEmpty()) << empty.err.toStdString();
    // The options as printed, given to the real program, find the controller.
    QProcess cli;
    cli.start(cliProgram(), QStringList{QStringLiteral("--port"), sim.pty} +
                                hint.split(QLatin1Char(' '), Qt::SkipEmptyParts));
    ASSERT_TRUE(cli.waitForStarted(5000));
    const CliResult found = finishCli(cli);
    ASSERT_EQ(found.code, 0) << found.err.toStdString();
    EXPECT_EQ(row(found.out, 1), QStringLiteral("1 01h DIP ON: 1 dcpid DCPID-20A V1.0 online"))
        << found.out.toStdString();
}
