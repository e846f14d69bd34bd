// backup, restore and compare as a user runs them. A simulated bus served over Modbus TCP in
// this process keeps its drives between commands (each --sim command starts a fresh bus), and
// its console backdoor changes them behind the program's back.
#include "cli/ExitCode.h"
#include "model/files/BackupFile.h"
#include "model/profile/ProfileRegistry.h"
#include "sim/SimBus.h"
#include "sim/TcpSimServer.h"
#include "tests/cli/CliTestSupport.h"
#include "tests/support/FileSizeLimit.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

class FileCommands : public ::testing::Test
{
protected:
    void SetUp() override
    {
        QString error;
        bus = SimBus::fromSpec(QStringLiteral("dbu200@1,dcpid@7"), &error);
        ASSERT_TRUE(bus) << qPrintable(error);
        server = std::make_unique<TcpSimServer>(bus, WireTiming(), false);
        ASSERT_TRUE(server->listen(QHostAddress::LocalHost, 0, &error)) << qPrintable(error);
        ASSERT_TRUE(dir.isValid());
    }

    // A command against the TCP bus; the DBU does not tell its variant, so it is named, and the
    // drives on the bus are listed (a restore names every drive its writes reach).
    CliRun cli(QStringList args)
    {
        return runCli(args << QStringLiteral("--tcp")
                           << QStringLiteral("127.0.0.1:%1").arg(server->port())
                           << QStringLiteral("--variant") << QStringLiteral("1=dbu200")
                           << QStringLiteral("--bus-drives") << QStringLiteral("1,7"));
    }

    QString path(const char* name) const { return dir.filePath(QString::fromLatin1(name)); }

    int held(int slave, const char* address)
    {
        const QStringList words =
            bus->control(slave, {QStringLiteral("get"), QString::fromLatin1(address)})
                .text.split(QLatin1Char(' '));
        return words.value(int(words.indexOf(QStringLiteral("="))) + 1).toInt();
    }

    void set(int slave, const char* address, int value)
    {
        ASSERT_TRUE(bus->control(slave, {QStringLiteral("set"), QString::fromLatin1(address),
                                         QString::number(value)})
                        .ok);
    }

    static QJsonObject json(const CliRun& r)
    {
        return QJsonDocument::fromJson(r.out.toUtf8()).object();
    }

    std::shared_ptr<SimBus> bus;
    std::unique_ptr<TcpSimServer> server;
    QTemporaryDir dir;
};

} // namespace

TEST_F(FileCommands, BackupChangeCompareRestoreCompare)
{
    const QString file = path("drives.json");
    CliRun r = cli({QStringLiteral("backup"), QStringLiteral("1"), QStringLiteral("7"),
                    QStringLiteral("-o"), file});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    // 12 blocks of settings; name and firmware came with the identification.
    EXPECT_TRUE(
        r.out.contains(QStringLiteral("drive 1 (DBU200-D): 69 settings read in 12 requests")))
        << qPrintable(r.out);
    {
        // ... and are in the file all the same.
        QFile saved(file);
        ASSERT_TRUE(saved.open(QIODevice::ReadOnly));
        const QJsonObject drive = QJsonDocument::fromJson(saved.readAll())
                                      .object()
                                      .value(QStringLiteral("devices"))
                                      .toArray()
                                      .at(0)
                                      .toObject();
        EXPECT_EQ(drive.value(QStringLiteral("firmware")).toString(), QStringLiteral("1.5"));
        EXPECT_EQ(drive.value(QStringLiteral("name")).toString(), QStringLiteral("DBU"));
    }
    EXPECT_TRUE(r.out.contains(QStringLiteral("wrote %1: 2 drive(s)").arg(file)))
        << qPrintable(r.out);

    set(1, "0xCA03", 1500); // spno2.speed
    set(7, "0x0086", 750);  // config.rated_current 7.50 A
    r = cli({QStringLiteral("compare"), file + QStringLiteral(":1"), QStringLiteral("1")});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_TRUE(r.out.contains(QStringLiteral("spno2.speed  1000 r/min  1500 r/min")))
        << qPrintable(r.out);
    EXPECT_TRUE(r.out.contains(QStringLiteral("1 difference(s) in 69 settings compared")))
        << qPrintable(r.out);

    // Without --yes the plan only; --dry-run the same.
    r = cli({QStringLiteral("restore"), file});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_TRUE(r.out.contains(QStringLiteral("drive 1 (DBU200-D): 1 of 69 settings differ")))
        << qPrintable(r.out);
    EXPECT_TRUE(
        r.out.contains(QStringLiteral("config.rated_current  5.00 A      7.50 A        write")))
        << qPrintable(r.out);
    EXPECT_TRUE(r.out.endsWith(QStringLiteral("nothing written; add --yes to write\n")));
    r = cli(
        {QStringLiteral("restore"), file, QStringLiteral("--dry-run"), QStringLiteral("--yes")});
    ASSERT_EQ(r.code, ExitOk);
    EXPECT_TRUE(r.out.endsWith(QStringLiteral("dry run: nothing written\n")));
    EXPECT_EQ(held(1, "0xCA03"), 1500);
    EXPECT_EQ(held(7, "0x0086"), 750);

    r = cli({QStringLiteral("restore"), file, QStringLiteral("--yes")});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.out + r.err);
    EXPECT_TRUE(r.out.contains(
        QStringLiteral("spno2.speed  1000 r/min  1500 r/min    written and verified")))
        << qPrintable(r.out);
    // Only the configuration was written to: its store command, not the PID's or the presets'.
    EXPECT_TRUE(r.out.contains(QStringLiteral("1 of 1 store commands written")))
        << qPrintable(r.out);
    EXPECT_TRUE(r.out.contains(QStringLiteral("not sent: nothing it stores is written")))
        << qPrintable(r.out);
    EXPECT_EQ(held(1, "0xCA03"), 1000);

    r = cli({QStringLiteral("compare"), file + QStringLiteral(":1"), QStringLiteral("1")});
    EXPECT_TRUE(r.out.contains(QStringLiteral("no differences (69 settings compared)")))
        << qPrintable(r.out);
    // Stored: a power cycle keeps the DC controller's restored value.
    ASSERT_TRUE(bus->control(7, {QStringLiteral("power-cycle")}).ok);
    r = cli({QStringLiteral("compare"), QStringLiteral("7"), file + QStringLiteral(":7")});
    EXPECT_EQ(r.code, ExitOk);
    EXPECT_TRUE(r.out.contains(QStringLiteral("no differences (24 settings compared)")))
        << qPrintable(r.out);
}

TEST_F(FileCommands, JsonForAllThreeCommands)
{
    const QString file = path("one.json");
    CliRun r = cli({QStringLiteral("backup"), QStringLiteral("1"), QStringLiteral("-o"), file,
                    QStringLiteral("--json")});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    QJsonObject o = json(r);
    EXPECT_TRUE(o.value(QStringLiteral("written")).toBool());
    EXPECT_EQ(o.value(QStringLiteral("drives"))
                  .toArray()
                  .at(0)
                  .toObject()
                  .value(QStringLiteral("requests"))
                  .toInt(),
              12);

    set(1, "0x1305", 25); // spno3.accel 2.5 s
    r = cli({QStringLiteral("compare"), file, QStringLiteral("1"), QStringLiteral("--json")});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    o = json(r);
    EXPECT_EQ(o.value(QStringLiteral("count")).toInt(), 1);
    const QJsonObject d = o.value(QStringLiteral("differences")).toArray().at(0).toObject();
    EXPECT_EQ(d.value(QStringLiteral("parameter")).toString(), QStringLiteral("spno3.accel"));
    EXPECT_EQ(d.value(QStringLiteral("a")).toString(), QStringLiteral("0.5 s"));
    EXPECT_EQ(d.value(QStringLiteral("b")).toString(), QStringLiteral("2.5 s"));

    r = cli({QStringLiteral("restore"), file, QStringLiteral("--yes"), QStringLiteral("--json")});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    const QJsonObject drive = json(r).value(QStringLiteral("drives")).toArray().at(0).toObject();
    EXPECT_EQ(drive.value(QStringLiteral("outcome")).toString(), QStringLiteral("done"));
    EXPECT_EQ(drive.value(QStringLiteral("verified")).toInt(), 1);
    EXPECT_EQ(drive.value(QStringLiteral("unchanged")).toInt(), 68);
    EXPECT_EQ(held(1, "0x1305"), 5);
}

TEST_F(FileCommands, ATamperedFileIsRefusedWithExit3AndNothingWritten)
{
    const QString file = path("tampered.json");
    ASSERT_EQ(cli({QStringLiteral("backup"), QStringLiteral("1"), QStringLiteral("-o"), file}).code,
              ExitOk);
    QFile f(file);
    ASSERT_TRUE(f.open(QIODevice::ReadWrite));
    QByteArray text = f.readAll();
    text.replace("\"registers\": [1000], \"value\": 1000",
                 "\"registers\": [1200], \"value\": 1200");
    f.resize(0);
    f.write(text);
    f.close();
    set(1, "0xCA05", 2000); // something a restore would write
    const CliRun r = cli({QStringLiteral("restore"), file, QStringLiteral("--yes")});
    EXPECT_EQ(r.code, ExitInvalid);
    EXPECT_TRUE(r.err.contains(QStringLiteral("the file was changed after it was written")))
        << qPrintable(r.err);
    EXPECT_EQ(held(1, "0xCA05"), 2000);
    EXPECT_EQ(held(1, "0xCA03"), 1000);
    EXPECT_EQ(cli({QStringLiteral("compare"), file, QStringLiteral("1")}).code, ExitInvalid);
}

TEST_F(FileCommands, AnotherVariantIsRefusedWithExit3)
{
    const QString file = path("dbu200.json");
    ASSERT_EQ(runCli({QStringLiteral("--sim=dbu200@1"), QStringLiteral("backup"),
                      QStringLiteral("1"), QStringLiteral("-o"), file})
                  .code,
              ExitOk);
    const CliRun r = runCli({QStringLiteral("--sim=dbu400@1"), QStringLiteral("restore"), file,
                             QStringLiteral("--yes")});
    EXPECT_EQ(r.code, ExitInvalid);
    EXPECT_TRUE(r.err.contains(QStringLiteral("machine number 1 is a DBU400-D4 (dbu400)")))
        << qPrintable(r.err);
    // A drive that is not there: a communication failure, nothing written.
    const CliRun absent = runCli({QStringLiteral("--sim=dcpid@7"), QStringLiteral("--timeout=20"),
                                  QStringLiteral("restore"), file, QStringLiteral("--yes")});
    EXPECT_EQ(absent.code, ExitCommunication);
    EXPECT_TRUE(absent.err.contains(QStringLiteral("nothing written"))) << qPrintable(absent.err);
}

TEST_F(FileCommands, AllDrivesOfASimulatedBusAndFactoryDefaults)
{
    const QString file = path("all.json");
    CliRun r = runCli({QStringLiteral("--sim=dbu200@1,dcpid@7"), QStringLiteral("backup"),
                       QStringLiteral("--all"), QStringLiteral("-o"), file});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    QString error;
    const auto loaded = BackupFile::load(file, ProfileRegistry::builtIn(), &error);
    ASSERT_TRUE(loaded) << qPrintable(error);
    EXPECT_EQ(loaded->slaves(), (QVector<int>{1, 7}));

    r = runCli({QStringLiteral("--sim=dbu200@1"), QStringLiteral("compare"), QStringLiteral("1"),
                QStringLiteral("--defaults")});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_TRUE(r.out.contains(QStringLiteral("B: factory defaults")));
    EXPECT_TRUE(r.out.contains(QStringLiteral("no differences"))) << qPrintable(r.out);
    EXPECT_TRUE(r.out.contains(QStringLiteral("with no factory default documented: "
                                              "va.countdown_days")))
        << qPrintable(r.out);
}

TEST_F(FileCommands, UsageErrors)
{
    const QString file = path("two.json");
    ASSERT_EQ(runCli({QStringLiteral("--sim=dbu200@1,dcpid@7"), QStringLiteral("backup"),
                      QStringLiteral("1"), QStringLiteral("7"), QStringLiteral("-o"), file})
                  .code,
              ExitOk);
    const QString sim = QStringLiteral("--sim=dbu200@1,dcpid@7");
    EXPECT_EQ(runCli({sim, QStringLiteral("backup"), QStringLiteral("1")}).code, ExitUsage);
    EXPECT_EQ(runCli({sim, QStringLiteral("backup"), QStringLiteral("-o"), file}).code, ExitUsage);
    CliRun r = runCli(
        {sim, QStringLiteral("restore"), file, QStringLiteral("--ids"), QStringLiteral("9")});
    EXPECT_EQ(r.code, ExitUsage);
    EXPECT_TRUE(
        r.err.contains(QStringLiteral("holds no drive with machine number 9; it holds 1, 7")))
        << qPrintable(r.err);
    r = runCli({sim, QStringLiteral("compare"), file, QStringLiteral("1")});
    EXPECT_EQ(r.code, ExitUsage);
    EXPECT_TRUE(r.err.contains(QStringLiteral("name one as"))) << qPrintable(r.err);
    EXPECT_EQ(
        runCli({QStringLiteral("compare"), path("missing.json"), QStringLiteral("--defaults")})
            .code,
        ExitUsage);
    EXPECT_EQ(runCli({QStringLiteral("compare"), file + QStringLiteral(":1"),
                      file + QStringLiteral(":7")})
                  .code,
              ExitInvalid); // a DBU and a DC controller: nothing to compare
    r = runCli({QStringLiteral("help"), QStringLiteral("compare")});
    EXPECT_TRUE(r.out.contains(QStringLiteral("exit 0 whether or not they differ")));
}

// A disk that fills (issue 28): the backup is not written, says why and exits non-zero, and
// the backup that was there stays whole.
TEST_F(FileCommands, ABackupOnAFullDiskKeepsTheOldFileAndFails)
{
    const QString file = path("b.json");
    ASSERT_EQ(runCli({QStringLiteral("--sim=dbu200@1,dcpid@7"), QStringLiteral("backup"),
                      QStringLiteral("1"), QStringLiteral("-o"), file})
                  .code,
              ExitOk);
    QFile before(file);
    ASSERT_TRUE(before.open(QIODevice::ReadOnly));
    const QByteArray old = before.readAll();
    before.close();
    CliRun r;
    {
        test::FileSizeLimit full(512); // smaller than any backup, larger than nothing
        ASSERT_TRUE(full.ok());
        r = runCli({QStringLiteral("--sim=dbu200@1,dcpid@7"), QStringLiteral("backup"),
                    QStringLiteral("1"), QStringLiteral("7"), QStringLiteral("-o"), file});
    }
    EXPECT_NE(r.code, ExitOk) << qPrintable(r.out + r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("cannot write %1").arg(file))) << qPrintable(r.err);
    EXPECT_FALSE(r.out.contains(QStringLiteral("wrote"))) << qPrintable(r.out);
    QFile after(file);
    ASSERT_TRUE(after.open(QIODevice::ReadOnly));
    EXPECT_EQ(after.readAll(), old);
}
