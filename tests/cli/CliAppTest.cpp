#include "CliApp.h"
#include "CliContext.h"
#include "CliTestSupport.h"
#include "ExitCode.h"

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
