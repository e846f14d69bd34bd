// Issue 24 item 8: names for machines and each family's switch notation, through the real
// opentop-cli against an opentop-sim process on a half-duplex pty with wire timing. The names
// are kept per bus in the settings the window reads too (BusMemory); this test process's own
// settings folder (PrivateUserDirs) is inherited by the programs it starts.
#include "tests/e2e/CliProcess.h"
#include "tests/e2e/SimProcess.h"

#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <csignal>

using namespace opentop::test;

namespace {

bool startSim(SimProcess& sim, const QString& devices)
{
    QString error;
    const bool ok = sim.start({QStringLiteral("--devices"), devices,
                               QStringLiteral("--wire-timing"), QStringLiteral("--half-duplex"),
                               QStringLiteral("--baud"), QStringLiteral("19200")},
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

TEST(CliNameE2e, AMachineNamedOnTheCommandLineShowsInTheScanAndTheBackup)
{
    SimProcess sim;
    ASSERT_TRUE(startSim(sim, QStringLiteral("dbu200@1,dcpid@7")));
    // Nothing named yet on this bus.
    CliResult r = runCliOn(sim.pty, {QStringLiteral("name")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("No machine of this bus has a name yet")))
        << r.err.toStdString();

    r = runCliOn(sim.pty, {QStringLiteral("name"), QStringLiteral("1"),
                           QStringLiteral("  Infeed conveyor 3 ")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("Machine number 1 (Infeed conveyor 3) is named now")))
        << r.out.toStdString();
    r = runCliOn(sim.pty, {QStringLiteral("name"), QStringLiteral("1")});
    EXPECT_EQ(r.out.trimmed(), QStringLiteral("Machine number 1 (Infeed conveyor 3)"));

    // A name the model refuses: exit 3, and the name kept is the one before.
    for (const QString& bad : {QStringLiteral("Line\nfeed"), QStringLiteral("Bell\x07"),
                               QString(41, QLatin1Char('x'))}) {
        r = runCliOn(sim.pty, {QStringLiteral("name"), QStringLiteral("1"), bad});
        EXPECT_EQ(r.code, 3) << bad.toStdString();
        EXPECT_TRUE(r.err.contains(QStringLiteral("Nothing was changed"))) << r.err.toStdString();
    }
    r = runCliOn(sim.pty, {QStringLiteral("--json"), QStringLiteral("name")});
    ASSERT_EQ(r.code, 0);
    const QJsonArray names =
        QJsonDocument::fromJson(r.out.toUtf8()).object().value(QStringLiteral("names")).toArray();
    ASSERT_EQ(names.size(), 1) << r.out.toStdString();
    EXPECT_EQ(names.at(0).toObject().value(QStringLiteral("name")).toString(),
              QStringLiteral("Infeed conveyor 3"));

    // The scan names it, and shows each family's own switches.
    r = runCliOn(sim.pty, {QStringLiteral("scan"), QStringLiteral("--from"), QStringLiteral("1"),
                           QStringLiteral("--to"), QStringLiteral("8")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_TRUE(r.out.section(QLatin1Char('\n'), 0, 0).contains(QStringLiteral("name")));
    EXPECT_TRUE(row(r.out, 1).startsWith(QStringLiteral("1 Infeed conveyor 3 01h SW1=0 SW2=1 dbu")))
        << r.out.toStdString();
    EXPECT_TRUE(row(r.out, 7).startsWith(QStringLiteral("7 07h DIP ON: 1,2,3 dcpid")))
        << r.out.toStdString();

    // A backup carries the name; compare names the drive by it.
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("line.json"));
    r = runCliOn(sim.pty, {QStringLiteral("backup"), QStringLiteral("1"), QStringLiteral("-o"),
                           file, QStringLiteral("--variant"), QStringLiteral("1=dbu200")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    QFile saved(file);
    ASSERT_TRUE(saved.open(QIODevice::ReadOnly));
    const QJsonObject device = QJsonDocument::fromJson(saved.readAll())
                                   .object()
                                   .value(QStringLiteral("devices"))
                                   .toArray()
                                   .at(0)
                                   .toObject();
    EXPECT_EQ(device.value(QStringLiteral("machineName")).toString(),
              QStringLiteral("Infeed conveyor 3"));
    r = runCliOn(sim.pty, {QStringLiteral("compare"), file, QStringLiteral("1"),
                           QStringLiteral("--variant"), QStringLiteral("1=dbu200")});
    EXPECT_TRUE(r.out.contains(QStringLiteral("drive 1 (Infeed conveyor 3)")))
        << r.out.toStdString() << r.err.toStdString();

    // An empty name removes it.
    r = runCliOn(sim.pty, {QStringLiteral("name"), QStringLiteral("1"), QString()});
    ASSERT_EQ(r.code, 0);
    EXPECT_TRUE(r.out.contains(QStringLiteral("Machine number 1 has no name now.")));
    r = runCliOn(sim.pty, {QStringLiteral("name"), QStringLiteral("1")});
    EXPECT_EQ(r.out.trimmed(), QStringLiteral("Machine number 1 has no name."));
    EXPECT_EQ(sim.terminate(), 0);
}

TEST(CliNameE2e, RestoringAnUnchangedDcControllerSendsNoStoreCommand)
{
    SimProcess sim;
    ASSERT_TRUE(startSim(sim, QStringLiteral("dcpid@7")));
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("dc.json"));
    CliResult r = runCliOn(
        sim.pty, {QStringLiteral("backup"), QStringLiteral("7"), QStringLiteral("-o"), file});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    // Nothing differs: nothing is written, and no store command either (said so).
    r = runCliOn(sim.pty, {QStringLiteral("--trace"), QStringLiteral("restore"), file,
                           QStringLiteral("--yes")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("not sent: nothing it stores is written")))
        << r.out.toStdString();
    // The trace shows every frame: no write (function 06 or 10) reached the controller.
    for (const QString& line : r.err.split(QLatin1Char('\n'))) {
        EXPECT_FALSE(line.contains(QStringLiteral("TX #7 07 06 ")) ||
                     line.contains(QStringLiteral("TX #7 07 10 ")))
            << line.toStdString();
    }
    EXPECT_TRUE(r.err.contains(QStringLiteral("TX #7 07 03 "))) << "the drive was read";
    EXPECT_EQ(sim.terminate(), 0);
}

TEST(CliNameE2e, ARestoreInterruptedBeforeItsStoreIsStoredByTheNextRun)
{
    SimProcess sim;
    ASSERT_TRUE(startSim(sim, QStringLiteral("dcpid@7")));
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("dc.json"));
    ASSERT_EQ(runCliOn(sim.pty,
                       {QStringLiteral("backup"), QStringLiteral("7"), QStringLiteral("-o"), file})
                  .code,
              0);
    // One configuration setting differs, and settings of the groups written after it (PID,
    // preset speeds): their writes and all stores come after the configuration's write.
    for (const char* set :
         {"set 7 0x0086 750", "set 7 0x0097 50", "set 7 0x00A2 600", "set 7 0x00A3 600"})
        sim.command(QString::fromLatin1(set));
    QProcess cli;
    cli.start(cliProgram(), {QStringLiteral("--port"), sim.pty, QStringLiteral("--trace"),
                             QStringLiteral("restore"), file, QStringLiteral("--yes")});
    ASSERT_TRUE(cli.waitForStarted(5000));
    QString trace;
    QElapsedTimer timer;
    timer.start();
    while (!trace.contains(QStringLiteral("TX #7 07 06 ")) && timer.elapsed() < 10000) {
        cli.waitForReadyRead(50);
        trace += QString::fromUtf8(cli.readAllStandardError());
    }
    ASSERT_TRUE(trace.contains(QStringLiteral("TX #7 07 06 "))) << trace.toStdString();
    ::kill(pid_t(cli.processId()), SIGINT);
    CliResult r = finishCli(cli);
    ASSERT_EQ(r.code, 130) << (r.out + r.err).toStdString();
    ASSERT_FALSE((trace + r.err).contains(QStringLiteral("TX #7 07 06 01 80")))
        << "interrupted before the store (else this test proves nothing)";
    // The configuration acts now but is not stored: another run (another process) has no
    // configuration left to write and still stores it, because the first run's unstored write
    // was kept for the bus.
    r = runCliOn(sim.pty, {QStringLiteral("--trace"), QStringLiteral("restore"), file,
                           QStringLiteral("--yes")});
    ASSERT_EQ(r.code, 0) << (r.out + r.err).toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("TX #7 07 06 01 80 00 01"))) << r.err.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("not stored yet"))) << r.out.toStdString();
    sim.command(QStringLiteral("power-cycle 7"));
    EXPECT_EQ(sim.get(7, 0x0086), 500); // the file's value, kept over power-off
    // Stored now: a third run stores nothing.
    r = runCliOn(sim.pty, {QStringLiteral("--trace"), QStringLiteral("restore"), file,
                           QStringLiteral("--yes")});
    ASSERT_EQ(r.code, 0);
    EXPECT_FALSE(r.err.contains(QStringLiteral("TX #7 07 06 01 80"))) << r.err.toStdString();
}
