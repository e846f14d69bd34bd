// `monitor --give-up SECONDS`: refused unless a number of seconds above 0 (exit 2, nothing
// opened), shown in the command's help, and no change while the link stays up; the CSV's note
// column is empty for samples. What a lost link does is tests/e2e/CliMonitorLinkE2eTest.
#include "cli/ExitCode.h"
#include "tests/cli/CliTestSupport.h"

#include <QFile>
#include <QTemporaryDir>
#include <gtest/gtest.h>

namespace {

QStringList monitor(const QStringList& extra)
{
    return QStringList{QStringLiteral("--sim"),      QStringLiteral("dbu200@1"),
                       QStringLiteral("monitor"),    QStringLiteral("1"),
                       QStringLiteral("--interval"), QStringLiteral("50"),
                       QStringLiteral("--count"),    QStringLiteral("2")} +
           extra;
}

} // namespace

TEST(MonitorGiveUp, WrongValuesAreAUsageError)
{
    for (const char* value : {"0", "-1", "x", "", "86401", "nan"}) {
        const CliRun r = runCli(monitor({QStringLiteral("--give-up"), QString::fromLatin1(value)}));
        EXPECT_EQ(r.code, opentop::ExitUsage) << value << ": " << qPrintable(r.err);
        EXPECT_TRUE(
            r.err.startsWith(QStringLiteral("error: --give-up must be a number of seconds")))
            << value << ": " << qPrintable(r.err);
        EXPECT_TRUE(r.out.isEmpty()) << value << ": nothing monitored";
    }
}

TEST(MonitorGiveUp, IsInTheHelpAndChangesNothingWhileTheLinkIsUp)
{
    const CliRun help = runCli({QStringLiteral("help"), QStringLiteral("monitor")});
    EXPECT_EQ(help.code, opentop::ExitOk);
    EXPECT_TRUE(help.out.contains(QStringLiteral("[--give-up SECONDS]"))) << qPrintable(help.out);
    EXPECT_TRUE(help.out.contains(QStringLiteral("  --give-up SECONDS  "))) << qPrintable(help.out);

    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("log.csv"));
    const CliRun r = runCli(monitor(
        {QStringLiteral("--give-up"), QStringLiteral("0.5"), QStringLiteral("--csv"), file}));
    EXPECT_EQ(r.code, opentop::ExitOk) << qPrintable(r.err);
    EXPECT_FALSE(r.err.contains(QStringLiteral("link"))) << qPrintable(r.err);
    QFile f(file);
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    const QStringList rows =
        QString::fromUtf8(f.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    ASSERT_EQ(rows.size(), 3); // header and two samples, no gap row
    EXPECT_TRUE(rows[0].endsWith(QStringLiteral(",alarm,note"))) << qPrintable(rows[0]);
    for (int i = 1; i < rows.size(); ++i) {
        EXPECT_TRUE(rows[i].endsWith(QLatin1Char(','))) << "an empty note: " << qPrintable(rows[i]);
        EXPECT_EQ(rows[i].count(QLatin1Char(',')), rows[0].count(QLatin1Char(',')));
    }
}
