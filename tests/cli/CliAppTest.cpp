#include "cli/CliApp.h"
#include "cli/CliContext.h"
#include "cli/ExitCode.h"
#include "tests/cli/CliTestSupport.h"

#include <QTextStream>
#include <gtest/gtest.h>

using namespace opentop;

TEST(CliApp, HelpListsCommandsAndExitCodes)
{
    const CliRun r = runCli({QStringLiteral("--help")});
    EXPECT_EQ(r.code, ExitOk);
    EXPECT_TRUE(r.out.contains(QStringLiteral("Exit codes: 0 success"))) << qPrintable(r.out);
    const CliRun none = runCli({});
    EXPECT_EQ(none.code, ExitUsage);
    EXPECT_TRUE(none.err.contains(QStringLiteral("Usage:")));
}

TEST(CliApp, UnknownCommandsAndOptionsAreUsageErrors)
{
    CliRun r = runCli({QStringLiteral("frobnicate")});
    EXPECT_EQ(r.code, ExitUsage);
    EXPECT_TRUE(r.err.contains(QStringLiteral("unknown command \"frobnicate\"")));
    r = runCli({QStringLiteral("--no-such-option"), QStringLiteral("ports")});
    EXPECT_EQ(r.code, ExitUsage);
}

TEST(CliApp, ParsesMachineNumberLists)
{
    QString error;
    EXPECT_EQ(*CliContext::parseIds(QStringLiteral("1,5-7,5"), &error), (QVector<int>{1, 5, 6, 7}));
    EXPECT_FALSE(CliContext::parseIds(QStringLiteral("0"), &error));
    EXPECT_FALSE(CliContext::parseIds(QStringLiteral("248"), &error));
    EXPECT_FALSE(CliContext::parseIds(QStringLiteral("9-3"), &error));
    EXPECT_FALSE(CliContext::parseIds(QStringLiteral("x"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("1–247")));
}

TEST(CliApp, JsonKeepsTheProfilesEnglish)
{
    const QString ko = QStringLiteral("ko");
    const QString program = QStringLiteral("opentop-cli");
    EXPECT_EQ(CliApp::profileLanguage({program, QStringLiteral("get"), QStringLiteral("1"),
                                       QStringLiteral("core.control_priority")},
                                      ko),
              ko);
    EXPECT_EQ(
        CliApp::profileLanguage({program, QStringLiteral("alarms"), QStringLiteral("--json")}, ko),
        QStringLiteral("en"));
    EXPECT_EQ(CliApp::profileLanguage({program, QStringLiteral("--json=1")}, ko),
              QStringLiteral("en"));
    // A value after "--" is no option.
    EXPECT_EQ(
        CliApp::profileLanguage(
            {program, QStringLiteral("set"), QStringLiteral("--"), QStringLiteral("--json")}, ko),
        ko);
    EXPECT_EQ(CliApp::profileLanguage({program, QStringLiteral("scan")}, QString()),
              QStringLiteral("en"));
}
