// Drives of different line formats on one bus, as delivered: opentop-cli over a pty against
// opentop-sim with wire timing on a half-duplex line, a DBU at 8N1 (the port's 19200 8N1) and a
// DC controller at its own format. At the port's format only the DBU answers and the scan says
// why a drive may be missing; with the DC controller's format given, scan, backup and monitor
// reach both, the port switched between transactions. Scans wait 60 ms per machine number: on
// a loaded machine the simulator answers late (the scan's rescue of late answers is
// CliScanE2e's and ScanLateAnswerE2e's subject, not this test's).
#include "tests/e2e/CliProcess.h"
#include "tests/e2e/SimProcess.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>

using namespace opentop::test;

namespace {

// The DC controller's own format: 8E1 at the bus's rate, or 8N2 at its factory rate (8N2 at
// the bus's rate would join it: a receiver checks only the first stop bit).
struct DcLine
{
    const char* format;
    int baud;
    QString token() const { return QStringLiteral("%1:%2").arg(baud).arg(QLatin1String(format)); }
    QString text() const { return QStringLiteral("%1 %2").arg(baud).arg(QLatin1String(format)); }
};

class MixedFormatsE2e : public ::testing::TestWithParam<DcLine>
{
protected:
    void SetUp() override
    {
        QString error;
        ASSERT_TRUE(sim.start({QStringLiteral("--devices"),
                               QStringLiteral("dbu200@1,dcpid@7{format=%1,baud=%2}")
                                   .arg(QLatin1String(GetParam().format))
                                   .arg(GetParam().baud),
                               QStringLiteral("--wire-timing"), QStringLiteral("--half-duplex"),
                               QStringLiteral("--baud"), QStringLiteral("19200")},
                              &error))
            << error.toStdString();
    }

    CliResult run(const QStringList& command)
    {
        QProcess cli;
        cli.start(cliProgram(),
                  QStringList{QStringLiteral("--port"), sim.pty, QStringLiteral("--variant"),
                              QStringLiteral("1=dbu200")} +
                      command);
        EXPECT_TRUE(cli.waitForStarted(5000));
        return finishCli(cli, 60000);
    }

    QStringList driveFormat() const
    {
        return {QStringLiteral("--drive-format"), QStringLiteral("7=") + GetParam().token()};
    }

    SimProcess sim;
};

QList<int> slavesIn(const QString& json)
{
    QList<int> slaves;
    const QJsonArray devices = QJsonDocument::fromJson(json.toUtf8())
                                   .object()
                                   .value(QStringLiteral("scan"))
                                   .toObject()
                                   .value(QStringLiteral("devices"))
                                   .toArray();
    for (const QJsonValue& d : devices)
        slaves << d.toObject().value(QStringLiteral("slave")).toInt();
    return slaves;
}

} // namespace

TEST_P(MixedFormatsE2e, AtThePortsFormatOnlyTheDbuAnswersAndTheScanSaysWhy)
{
    const CliResult r =
        run({QStringLiteral("scan"), QStringLiteral("--wait"), QStringLiteral("60"),
             QStringLiteral("--to"), QStringLiteral("10"), QStringLiteral("--json")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_EQ(slavesIn(r.out), QList<int>{1}) << r.out.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("another line format than 19200 8N1")))
        << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("--drive-format"))) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("--try-formats"))) << r.err.toStdString();
}

TEST_P(MixedFormatsE2e, WithTheDrivesFormatScanBackupAndMonitorReachBoth)
{
    CliResult r = run(driveFormat() + QStringList{QStringLiteral("scan"), QStringLiteral("--wait"),
                                                  QStringLiteral("60"), QStringLiteral("--to"),
                                                  QStringLiteral("10")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("2 drives found"))) << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(GetParam().text())) << r.out.toStdString();
    EXPECT_FALSE(r.err.contains(QStringLiteral("--try-formats"))) << r.err.toStdString();

    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("mixed.json"));
    r = run(driveFormat() + QStringList{QStringLiteral("backup"), QStringLiteral("1"),
                                        QStringLiteral("7"), QStringLiteral("-o"), file});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("drive 1 (DBU200-D)"))) << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("drive 7"))) << r.out.toStdString();

    r = run(driveFormat() + QStringList{QStringLiteral("monitor"), QStringLiteral("1"),
                                        QStringLiteral("7"), QStringLiteral("--count"),
                                        QStringLiteral("3"), QStringLiteral("--interval"),
                                        QStringLiteral("100")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_EQ(r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts).size(), 2 + 6)
        << r.out.toStdString(); // a header per family, 3 samples of each drive
}

TEST_P(MixedFormatsE2e, AScanToldToTryOtherFormatsFindsTheDcController)
{
    const CliResult r =
        run({QStringLiteral("scan"), QStringLiteral("--wait"), QStringLiteral("60"),
             QStringLiteral("--to"), QStringLiteral("8"), QStringLiteral("--try-formats")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("2 drives found"))) << r.out.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("Machine number 7 answered at ") + GetParam().text()))
        << r.err.toStdString();
}

INSTANTIATE_TEST_SUITE_P(DcFormats, MixedFormatsE2e,
                         ::testing::Values(DcLine{"8E1", 19200}, DcLine{"8N2", 9600}));
