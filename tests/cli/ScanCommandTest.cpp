// `opentop-cli scan` in process on simulated buses (--sim): small ranges and short waits keep
// these fast; the full-range timing is opentop-bench's business.
#include "cli/ExitCode.h"
#include "tests/cli/CliTestSupport.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

CliRun scan(const QString& sim, const QStringList& args)
{
    return runCli(QStringList{QStringLiteral("--sim"), sim, QStringLiteral("scan"),
                              QStringLiteral("--wait"), QStringLiteral("10")} +
                  args);
}

// The table row that starts with machine number `slave`.
QString row(const QString& out, int slave)
{
    for (const QString& line : out.split(QLatin1Char('\n'))) {
        if (line.trimmed().startsWith(QString::number(slave) + QLatin1Char(' ')))
            return line;
    }
    return QString();
}

} // namespace

TEST(ScanCommand, PrintsATableOfTheDrivesFound)
{
    const CliRun r = scan(QStringLiteral("dbu200@1,dcpid@7,dbu400@150"),
                          {QStringLiteral("--from"), QStringLiteral("1"), QStringLiteral("--to"),
                           QStringLiteral("10")});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    const QStringList header =
        r.out.section(QLatin1Char('\n'), 0, 0).simplified().split(QLatin1Char(' '));
    EXPECT_EQ(header,
              (QStringList{QStringLiteral("ID"), QStringLiteral("hex"), QStringLiteral("switches"),
                           QStringLiteral("family"), QStringLiteral("model"),
                           QStringLiteral("firmware"), QStringLiteral("state")}));
    EXPECT_EQ(row(r.out, 1).simplified(),
              QStringLiteral("1 01h SW1=0 SW2=1 dbu DBU200-D V1.5 online"));
    // Each family's own switches: the DC controller's DIP switches 1–7 in binary.
    EXPECT_EQ(row(r.out, 7).simplified(),
              QStringLiteral("7 07h DIP ON: 1,2,3 dcpid DCPID-20A V1.0 online"));
    EXPECT_TRUE(row(r.out, 150).isEmpty()) << "150 is outside --to 10";
    EXPECT_TRUE(r.out.contains(QStringLiteral("2 drives found in "))) << qPrintable(r.out);
    // Progress goes to standard error, one line per 10 % when it is not a terminal.
    EXPECT_EQ(r.err.count(QStringLiteral("scan: ")), 10) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("scan: 100 % (10 of 10 machine numbers), 2 found")));
}

TEST(ScanCommand, VariantsComeFromTheBusListOrTheCommandLine)
{
    // "dbu" names the family only: the drive does not say whether it is a DBU200 or DBU400.
    CliRun r =
        scan(QStringLiteral("dbu@3,dbu400@4"), {QStringLiteral("--from"), QStringLiteral("3"),
                                                QStringLiteral("--to"), QStringLiteral("4")});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_TRUE(row(r.out, 3).contains(QStringLiteral("DBU — variant unknown")))
        << qPrintable(r.out);
    EXPECT_TRUE(row(r.out, 4).contains(QStringLiteral("DBU400-D4"))) << qPrintable(r.out);

    r = scan(QStringLiteral("dbu@3"),
             {QStringLiteral("--from"), QStringLiteral("3"), QStringLiteral("--to"),
              QStringLiteral("3"), QStringLiteral("--variant"), QStringLiteral("3=dbu400")});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_TRUE(row(r.out, 3).contains(QStringLiteral("DBU400-D4"))) << qPrintable(r.out);
    EXPECT_TRUE(r.out.contains(QStringLiteral("1 drive found in "))) << qPrintable(r.out);
}

TEST(ScanCommand, JsonDescribesTheScanAndEveryDevice)
{
    const CliRun r = scan(QStringLiteral("dbu@2,dcpid@5"),
                          {QStringLiteral("--json"), QStringLiteral("--from"), QStringLiteral("2"),
                           QStringLiteral("--to"), QStringLiteral("6")});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.err);
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(r.out.toUtf8(), &error);
    ASSERT_EQ(error.error, QJsonParseError::NoError) << qPrintable(r.out);
    const QJsonObject scanObject = doc.object().value(QStringLiteral("scan")).toObject();
    EXPECT_EQ(scanObject.value(QStringLiteral("from")).toInt(), 2);
    EXPECT_EQ(scanObject.value(QStringLiteral("to")).toInt(), 6);
    EXPECT_EQ(scanObject.value(QStringLiteral("waitMs")).toInt(), 10);
    EXPECT_GE(scanObject.value(QStringLiteral("elapsedMs")).toInt(-1), 0);
    const QJsonArray devices = scanObject.value(QStringLiteral("devices")).toArray();
    ASSERT_EQ(devices.size(), 2);
    const QJsonObject dbu = devices.at(0).toObject();
    EXPECT_EQ(QStringList(dbu.keys()),
              (QStringList{QStringLiteral("detail"), QStringLiteral("family"),
                           QStringLiteral("firmware"), QStringLiteral("group"),
                           QStringLiteral("hex"), QStringLiteral("line"), QStringLiteral("model"),
                           QStringLiteral("name"), QStringLiteral("slave"), QStringLiteral("state"),
                           QStringLiteral("switches"), QStringLiteral("variant")}));
    // A DBU's communication group, null when disabled.
    EXPECT_TRUE(dbu.value(QStringLiteral("group")).isNull());
    // Answered at the port's own format: no per-drive line format.
    EXPECT_EQ(dbu.value(QStringLiteral("line")).toString(), QString());
    EXPECT_EQ(dbu.value(QStringLiteral("slave")).toInt(), 2);
    EXPECT_EQ(dbu.value(QStringLiteral("hex")).toString(), QStringLiteral("02h"));
    EXPECT_EQ(dbu.value(QStringLiteral("switches")).toString(), QStringLiteral("SW1=0 SW2=2"));
    EXPECT_EQ(dbu.value(QStringLiteral("family")).toString(), QStringLiteral("dbu"));
    EXPECT_EQ(dbu.value(QStringLiteral("variant")).toString(), QString());
    EXPECT_EQ(dbu.value(QStringLiteral("firmware")).toString(), QStringLiteral("1.5"));
    EXPECT_EQ(dbu.value(QStringLiteral("state")).toString(), QStringLiteral("present"));
    EXPECT_TRUE(
        dbu.value(QStringLiteral("detail")).toString().contains(QStringLiteral("--variant")));
    const QJsonObject dc = devices.at(1).toObject();
    EXPECT_EQ(dc.value(QStringLiteral("slave")).toInt(), 5);
    EXPECT_EQ(dc.value(QStringLiteral("family")).toString(), QStringLiteral("dcpid"));
    EXPECT_EQ(dc.value(QStringLiteral("model")).toString(), QStringLiteral("DCPID-20A"));
}

TEST(ScanCommand, BadArgumentsAreUsageErrors)
{
    const QList<QStringList> bad{
        {QStringLiteral("--from"), QStringLiteral("0")},
        {QStringLiteral("--to"), QStringLiteral("248")},
        {QStringLiteral("--from"), QStringLiteral("10"), QStringLiteral("--to"),
         QStringLiteral("5")},
        {QStringLiteral("--from"), QStringLiteral("x")},
        {QStringLiteral("--wait"), QStringLiteral("4")},
        {QStringLiteral("--wait"), QStringLiteral("5001")},
        {QStringLiteral("17")},
    };
    for (const QStringList& args : bad) {
        const CliRun r = runCli(QStringList{QStringLiteral("--sim"), QStringLiteral("dbu200@1"),
                                            QStringLiteral("scan")} +
                                args);
        EXPECT_EQ(r.code, ExitUsage) << qPrintable(args.join(QLatin1Char(' ')));
        EXPECT_TRUE(r.err.startsWith(QStringLiteral("error: "))) << qPrintable(r.err);
        EXPECT_TRUE(r.out.isEmpty());
    }
    const CliRun r = runCli({QStringLiteral("--sim"), QStringLiteral("dbu200@1"),
                             QStringLiteral("scan"), QStringLiteral("--from"), QStringLiteral("10"),
                             QStringLiteral("--to"), QStringLiteral("5")});
    EXPECT_TRUE(r.err.contains(QStringLiteral("--from 10 is after --to 5"))) << qPrintable(r.err);
}

TEST(ScanCommand, NoDriveAnsweringExplainsWhatToCheck)
{
    const CliRun r =
        scan(QStringLiteral("dbu200@100"), {QStringLiteral("--from"), QStringLiteral("1"),
                                            QStringLiteral("--to"), QStringLiteral("5")});
    EXPECT_EQ(r.code, ExitCommunication);
    EXPECT_TRUE(r.out.contains(QStringLiteral("0 drives found"))) << qPrintable(r.out);
    for (const char* hint : {"No drive answered at machine numbers 1–5", "A/B polarity",
                             "baud rate and parity", "termination"})
        EXPECT_TRUE(r.err.contains(QString::fromUtf8(hint))) << hint << "\n" << qPrintable(r.err);
}

TEST(ScanCommand, WaitOutsideWhatTheTransportAllowsIsAUsageError)
{
    CliRun r = runCli({QStringLiteral("--sim"), QStringLiteral("dbu200@1"), QStringLiteral("scan"),
                       QStringLiteral("--to"), QStringLiteral("1"), QStringLiteral("--wait"),
                       QStringLiteral("9")});
    EXPECT_EQ(r.code, ExitUsage);
    EXPECT_TRUE(r.err.contains(QStringLiteral("10"))) << qPrintable(r.err);
    r = runCli({QStringLiteral("--sim"), QStringLiteral("dbu200@1"), QStringLiteral("scan"),
                QStringLiteral("--to"), QStringLiteral("1"), QStringLiteral("--wait"),
                QStringLiteral("10")});
    EXPECT_EQ(r.code, ExitOk) << qPrintable(r.err);
    EXPECT_TRUE(r.err.contains(QStringLiteral("10 ms each"))) << qPrintable(r.err);
}
