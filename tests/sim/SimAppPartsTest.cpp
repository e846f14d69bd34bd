// opentop-sim's command line and console.
#include "tests/sim/SimTestSupport.h"

#include "sim/SimConsole.h"
#include "sim/SimOptions.h"

using namespace opentop;
using namespace opentop::test;

namespace {

std::optional<SimOptions> parse(const char* line, QString* error)
{
    return SimOptions::parse(QString::fromLatin1(line).split(QLatin1Char(' '), Qt::SkipEmptyParts),
                             error);
}

} // namespace

TEST(SimOptions, ParsesEveryOption)
{
    QString error;
    auto o = parse("--devices dbu200@1 --pty /tmp/x --tcp :5020 --baud 9600 --parity e "
                   "--wire-timing --turnaround 3.5 --faults drop=0.1 --seed 9 --quiet",
                   &error);
    ASSERT_TRUE(o) << error.toStdString();
    EXPECT_EQ(o->devices, QStringLiteral("dbu200@1"));
    EXPECT_TRUE(o->pty);
    EXPECT_EQ(o->ptyLink, QStringLiteral("/tmp/x"));
    EXPECT_TRUE(o->tcp);
    EXPECT_EQ(o->tcpHost, QStringLiteral("127.0.0.1"));
    EXPECT_EQ(o->tcpPort, 5020);
    EXPECT_EQ(o->baud, 9600);
    EXPECT_EQ(o->parity, 'E');
    EXPECT_TRUE(o->wireTiming);
    EXPECT_DOUBLE_EQ(o->turnaroundMs, 3.5);
    EXPECT_DOUBLE_EQ(o->faults.drop, 0.1);
    EXPECT_EQ(o->seed, 9u);
    EXPECT_TRUE(o->quiet);

    o = parse("--devices=dcpid@7 --pty --seed 3", &error);
    ASSERT_TRUE(o);
    EXPECT_TRUE(o->pty);
    EXPECT_TRUE(o->ptyLink.isEmpty());
    o = parse("--devices dcpid@7 --tcp 0.0.0.0:0", &error);
    ASSERT_TRUE(o);
    EXPECT_FALSE(o->pty); // --tcp alone: no pty
    EXPECT_EQ(o->tcpHost, QStringLiteral("0.0.0.0"));
    EXPECT_TRUE(parse("--devices dcpid@7", &error)->pty); // pty by default
    EXPECT_TRUE(parse("--help", &error)->help);
}

TEST(SimOptions, BadArgumentsNameTheAllowedValues)
{
    QString error;
    EXPECT_FALSE(parse("--pty", &error));
    EXPECT_TRUE(error.contains(QStringLiteral("--devices"))) << error.toStdString();
    EXPECT_FALSE(parse("--devices dbu200@1 --baud 1000", &error));
    EXPECT_TRUE(error.contains(QStringLiteral("115200"))) << error.toStdString();
    EXPECT_FALSE(parse("--devices dbu200@1 --parity X", &error));
    EXPECT_TRUE(error.contains(QStringLiteral("N, E or O"))) << error.toStdString();
    EXPECT_FALSE(parse("--devices dbu200@1 --faults drop=7", &error));
    EXPECT_FALSE(parse("--devices dbu200@1 --tcp host:99999", &error));
    EXPECT_FALSE(parse("--devices dbu200@1 --turnaround -1", &error));
    EXPECT_FALSE(parse("--devices dbu200@1 --seed x", &error));
    EXPECT_FALSE(parse("--devices dbu200@1 --frobnicate", &error));
    EXPECT_TRUE(error.contains(QStringLiteral("--wire-timing"))) << error.toStdString();
    EXPECT_FALSE(parse("--devices dbu200@1 --baud", &error));
}

TEST(SimConsole, CommandsAndErrors)
{
    SimFixture sim("dbu200@1,dcpid@7");
    SimConsole console(sim.bus);
    EXPECT_TRUE(
        console.execute(QStringLiteral("help")).text.contains(QStringLiteral("ignore-stop")));
    const SimControlResult list = console.execute(QStringLiteral("list"));
    EXPECT_TRUE(list.text.contains(QStringLiteral("1 dbu200"))) << list.text.toStdString();
    EXPECT_TRUE(list.text.contains(QStringLiteral("7 dcpid"))) << list.text.toStdString();
    EXPECT_TRUE(console.execute(QStringLiteral("vr 1 900")).ok);
    EXPECT_EQ(sim.raw(1, "spno1.speed"), 900);
    EXPECT_TRUE(console.execute(QStringLiteral("  set 7 0x0014 250 ")).ok);
    EXPECT_EQ(sim.raw(7, "status.ai_diff"), 250);
    EXPECT_TRUE(
        console.execute(QStringLiteral("get 7 0x0016")).text.contains(QStringLiteral("= 250")));
    EXPECT_FALSE(console.execute(QStringLiteral("vr 1 9000")).ok);
    EXPECT_FALSE(console.execute(QStringLiteral("vr 7 100")).ok); // not a DBU
    EXPECT_FALSE(console.execute(QStringLiteral("vr")).ok);
    EXPECT_FALSE(console.execute(QStringLiteral("vr x 100")).ok);
    EXPECT_FALSE(console.execute(QStringLiteral("dance 1")).ok);
    EXPECT_TRUE(console.execute(QStringLiteral("power-cycle 7")).ok);
    EXPECT_TRUE(console.execute(QString()).ok);
    EXPECT_FALSE(console.quitRequested());
    console.execute(QStringLiteral("quit"));
    EXPECT_TRUE(console.quitRequested());
}
